#include "elasticity_operator.templates.h"

namespace FrictionalContact
{
  template class ElasticityOperator<3, double>;
  template class ElasticityOperator<3, float>;
} // namespace FrictionalContact
