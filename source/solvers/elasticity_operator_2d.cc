#include "elasticity_operator.templates.h"

namespace FrictionalContact
{
  template class ElasticityOperator<2, double>;
  template class ElasticityOperator<2, float>;
} // namespace FrictionalContact
