#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/model/contact_operator.h>

#include <vector>

namespace FrictionalContact
{
  using namespace dealii;

  /**
   * What the prescribed data do over one increment: the increment of the
   * prescribed displacements (the lifting), the change of the load factor,
   * and the rigid obstacle's and the rigid tool's motions. It tells whether
   * an increment goes on the way the last one went (continues()), the
   * condition for starting its solve from the last increment's motion:
   * where a die stops pressing and slides, or a load is taken off, that
   * motion points the wrong way.
   */
  template <int dim>
  class IncrementDrive
  {
  public:
    /// No drive: continues() nothing and nothing continues it.
    IncrementDrive() = default;

    /// The drive of an increment whose prescribed displacements move by
    /// @p lifting, with the rest of its parts (rigid_parts_of()).
    IncrementDrive(const TrilinosWrappers::MPI::Vector &lifting,
                   std::vector<std::vector<double>>     rigid_parts);

    /// The parts of the drive besides the lifting, of the increment from
    /// @p t_start to @p t_end whose load factor changes by
    /// @p load_factor_change: that change, the obstacle's displacement,
    /// and, with a tool, its translation and its angle.
    static std::vector<std::vector<double>>
    rigid_parts_of(const double                load_factor_change,
                   const ContactOperator<dim> &contact,
                   const double                t_start,
                   const double                t_end);

    /**
     * Whether this increment, of length @p length, goes on the way @p last,
     * of length @p last_length, went: each part of its drive (the lifting,
     * the load factor's change, the obstacle's displacement, the tool's
     * translation and its angle) is zero in both, or points within 25
     * degrees of the last one's with a size between half and twice the
     * last one's scaled by the ratio of the lengths. Collective.
     */
    bool
    continues(const IncrementDrive &last,
              const double          length,
              const double          last_length) const;

  private:
    /// Whether two parts of drives with the dot product @p dot and the
    /// squared norms @p this_norm2 and @p last_norm2 go the same way, the
    /// increments' lengths in the ratio @p ratio.
    static bool
    same_way(const double dot,
             const double this_norm2,
             const double last_norm2,
             const double ratio);

    TrilinosWrappers::MPI::Vector lifting;
    /// The load factor's change, the obstacle's displacement, the tool's
    /// translation and its angle over the increment (the same on every
    /// rank).
    std::vector<std::vector<double>> rigid_parts;
  };
} // namespace FrictionalContact
