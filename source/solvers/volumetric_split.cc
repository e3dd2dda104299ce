#include <frictional_contact/solvers/volumetric_split.h>

namespace FrictionalContact
{
  namespace MixedVolumetric
  {
    BlockVector
    make_block_vector(const VolumetricSplit &split)
    {
      return BlockVector(
        std::vector<IndexSet>{
          split.reduced_stiffness->locally_owned_domain_indices(),
          split.compliance->locally_owned_elements()},
        split.reduced_stiffness->get_mpi_communicator());
    }



    void
    consistent_pressure(const VolumetricSplit &split,
                        const Vector          &u,
                        Vector                &p)
    {
      split.divergence->vmult(p, u);
      const double *C = split.compliance->begin();
      double       *P = p.begin();
      for (unsigned int e = 0; e < p.locally_owned_size(); ++e)
        P[e] /= C[e];
    }
  } // namespace MixedVolumetric
} // namespace FrictionalContact
