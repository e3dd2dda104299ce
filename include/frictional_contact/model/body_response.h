#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <frictional_contact/base/placed_minimum.h>
#include <frictional_contact/model/cell_matrix_positions.h>
#include <frictional_contact/model/gradient_contraction.h>
#include <frictional_contact/model/elastic_body.h>
#include <frictional_contact/material/material.h>
#include <frictional_contact/model/quadrature_history.h>
#include <frictional_contact/model/reference_gradients.h>

#include <array>
#include <memory>
#include <vector>

namespace FrictionalContact
{
  /// What a cell's quadrature points say, averaged over the cell: for the
  /// VTU files and the CSV tables.
  template <int dim>
  struct CellState
  {
    /// The in-plane stress, the out-of-plane normal stress (2D) and the
    /// mean stress trace(sigma)/3 of the 3D stress.
    SymmetricTensor<2, dim> stress;
    double                  out_of_plane_stress = 0;
    double                  mean_stress         = 0;
    /// The von Mises equivalent stress sqrt(3/2) |dev sigma| (3D stress).
    double von_mises_stress = 0;
    /// The equivalent plastic strain and the plastic strain tensor (3D).
    double                equivalent_plastic_strain = 0;
    SymmetricTensor<2, 3> plastic_strain;
    /// 0: never yielded; 1: plastic strain, now elastic (unloaded); 2: a
    /// point flows (on the yield surface).
    unsigned int yield_state = 0;
    /// J = det F, the volume ratio (1 at small strain).
    double jacobian = 1;
  };



  /**
   * The bodies' response to a displacement u: at the quadrature points of
   * the locally owned cells (the Gauss points, or a finite-strain body's
   * Gauss-Lobatto points: <Material/Quadrature>), the strain of the element (the standard Q1
   * element's, or the B-bar element's with the cell average of the
   * dilatation as its volumetric part; at finite strain the Green-Lagrange
   * strain of F = I + Grad u), the stress of each body's law from
   * the committed history, and from them the internal force f_int(u), the
   * tangent K_T(u), the history that goes with u, and the cell averages
   * for output. The one place where stress is recovered: the residual,
   * the VTU files and the tables all take it from here.
   *
   * The element: f_i = int grad^s phi_i : sigma + (div_bar phi_i - div
   * phi_i) pi, with pi the law's volumetric stress (zero term for the
   * standard element), and K_T its derivative. At finite strain (total
   * Lagrangian): f_i = int Grad phi_i : F S, and K_T its derivative, with
   * the material part F^T Grad phi_i : dS/dE : F^T Grad phi_j and the
   * geometric part Grad phi_i : Grad phi_j S. A point where det F <= 0
   * (an inverted element) stops the evaluation with a SolverError that
   * names the cell, on every rank, so that the increment can be cut.
   */
  template <int dim>
  class BodyResponse
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    BodyResponse(const ElasticBody<dim>       &body,
                 const Materials<dim>         &materials,
                 QuadratureHistory<dim>       &history);

    /**
     * f_int(u) for @p u_ghosted (with ghost entries) into @p force,
     * distributed with @p distribute (all constraints: zero at the held
     * dofs; or the hanging-node ones), and if @p tangent is given K_T(u)
     * into it (all constraints). Returns how many quadrature points flow
     * plastically, on all ranks. Collective.
     */
    types::global_dof_index
    internal_force(const Vector                    &u_ghosted,
                   const AffineConstraints<double> &distribute,
                   Vector                          &force,
                   TrilinosWrappers::SparseMatrix  *tangent) const;

    /**
     * f_int(u) into @p force and K_T(u) into @p matrix (all constraints),
     * for @p u_ghosted. After a first call (which assembles every cell),
     * only the cells that flow plastically now or did at the last call are
     * assembled again (their last contribution taken out): every other
     * cell adds its elastic matrix, which does not change. Valid while the
     * history and the mesh stay: commit() and forget_tangent() start anew.
     * Returns the points that flow plastically. Collective.
     */
    types::global_dof_index
    update_tangent(const Vector                    &u_ghosted,
                   const AffineConstraints<double> &constraints,
                   Vector                          &force,
                   TrilinosWrappers::SparseMatrix  &matrix);

    /// sqrt(sum over the cells of |f_e|^2) of the last internal_force() or
    /// update_tangent(): the size of the forces in the bodies, which
    /// self-equilibrated stresses (after unloading) leave large where
    /// f_int itself vanishes.
    double
    element_force_norm() const
    {
      return element_force_size;
    }

    /// The smallest det F at @p u_ghosted on all ranks, at the points and
    /// the corners of the finite-strain cells, and the centre of its cell
    /// (nothing met without a finite-strain body). Collective.
    PlacedMinimum<dim>
    smallest_jacobian(const Vector &u_ghosted) const;

    /// The matrix is no longer the last tangent (K assembled anew, a new
    /// mesh): the next update_tangent() assembles every cell.
    void
    forget_tangent();

    /// After a new mesh (Model::assemble()): forgets the tangent and, where
    /// some law is nonlinear (its cells evaluated at every Newton step),
    /// takes the cells' ReferenceGradients.
    void
    new_mesh();

    /// Makes the history of u (an accepted increment's) the committed one.
    void
    commit(const Vector &u_ghosted);

    /// Whether some body is at finite strain (the cell states then hold
    /// the Cauchy stress and det F).
    bool
    finite_strain() const
    {
      return materials.any_finite_strain();
    }

    /// The averages of each locally owned cell, by active_cell_index()
    /// (default values on the other cells).
    std::vector<CellState<dim>>
    cell_states(const Vector &u_ghosted) const;

  private:
    /// What one cell needs: FEValues of the vertices' scalar Q1 functions
    /// (the system's copies of them would be copied out at every cell) on
    /// the 2 x 2 (x 2) Gauss points and on the 3 x 3 (x 3) Gauss-Lobatto
    /// points (a body with <Material/Quadrature> = Gauss-Lobatto), the
    /// local displacement, the strains and the responses at the points of
    /// the cell's rule.
    struct CellScratch
    {
      explicit CellScratch(const FiniteElement<dim> &fe);

      /// The FEValues of the rule of the last cell evaluate_cell() took.
      FEValues<dim> &
      fe_values()
      {
        return corner_points ? lobatto_values : gauss_values;
      }

      /// grad N_a of the vertices' Q1 functions at point q (the shape
      /// function of dof (a, c) is N_a e_c), a = 0, ..., n_vertices - 1.
      const Tensor<1, dim> *
      gradients_at(const unsigned int q) const
      {
        return gradients + q * GeometryInfo<dim>::vertices_per_cell;
      }

      /// The Gauss points: those of the history (no law with history takes
      /// the Gauss-Lobatto points).
      QGauss<dim>                          gauss;
      FEValues<dim>                        gauss_values;
      FEValues<dim>                        lobatto_values;
      bool                                 corner_points = false;
      /// The dof of component c at vertex a: dof[a][c].
      std::vector<std::array<unsigned int, dim>> dof;
      dealii::Vector<double>               u;
      std::vector<types::global_dof_index> dof_indices;
      /// The cell's points: their number, JxW and the gradients of the
      /// vertices' functions (gradients_at()), from the ReferenceGradients
      /// where they are kept, else copied from the FEValues into own_JxW
      /// and own_gradients.
      unsigned int                n_points  = 0;
      const double               *JxW       = nullptr;
      const Tensor<1, dim>       *gradients = nullptr;
      std::vector<double>         own_JxW;
      std::vector<Tensor<1, dim>> own_gradients;
      /// The cell averages of div phi_i.
      std::vector<double>                      mean_divergence;
      std::vector<MaterialResponse<dim>>       responses;
      /// The strains at the points.
      std::vector<SymmetricTensor<2, dim>>     strain;
      bool                                     finite_strain = false;
      /// Which volume ratio the cell's law takes
      /// (MaterialModel::volume_ratio()).
      typename MaterialModel<dim>::VolumeRatio volume_ratio =
        MaterialModel<dim>::VolumeRatio::none;
      /// Of a cell of an axisymmetric scene (evaluate_revolved_cell()):
      /// whether the last cell was one, whether its law takes the B-bar
      /// element, the radius r and the values N_a of the vertices'
      /// functions at its points (N_a at point q: values[q * n_vertices
      /// + a]), its 3D law's volume ratio, F with the hoop stretch (finite
      /// strain) and the 3D law's responses. Its JxW carry 2 pi r.
      bool                                      revolved = false;
      bool                                      revolved_mean_dilatation = false;
      std::vector<double>                       radius;
      std::vector<double>                       values;
      typename MaterialModel<3>::VolumeRatio    revolved_volume_ratio =
        MaterialModel<3>::VolumeRatio::none;
      std::vector<Tensor<2, 3>>                 revolved_deformation;
      std::vector<MaterialResponse<3>>          revolved_responses;
      /// F = I + Grad u and det F at the points of a finite-strain cell;
      /// the smallest det F met at the points and the vertices
      /// (smallest_corner_jacobian()) since the scratch was made, and the
      /// centre of its cell.
      std::vector<Tensor<2, dim>>              deformation_gradient;
      std::vector<double>                      jacobian;
      PlacedMinimum<dim>                       smallest_jacobian;
      /// The cell matrix of the points' tangents, formed as one product.
      GradientContraction<dim>                 contraction;
      FullMatrix<double>                       matrix;
      dealii::Vector<double>                   force;
    };

    /// The responses at the points of @p cell (from the committed
    /// history; the new history into @p new_history if given).
    void
    evaluate_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                  const Vector                                         &u_ghosted,
                  const bool                                            with_tangent,
                  CellScratch                                          &scratch,
                  double                                               *new_history) const;

    /// evaluate_cell() for a cell of an axisymmetric scene: the strain
    /// (or F) with its hoop part u_r / r (F_33 = 1 + u_r / R), the body's
    /// 3D law, the weight 2 pi r in the points' JxW
    /// (body_response_revolved.cc).
    void
    evaluate_revolved_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                           const Vector                                         &u_ghosted,
                           const bool                                            with_tangent,
                           CellScratch                                          &scratch,
                           double                                               *new_history) const;

    /// The cell force (and matrix) of such a cell, of either kinematics:
    /// the virtual gradient of dof (a, c) is e_c (x) Grad N_a with N_a / r
    /// in the hoop entry (3, 3) for c = r.
    void
    revolved_force_and_tangent(const bool with_tangent, CellScratch &scratch) const;

    /// The cell averages of such a cell's responses into @p state.
    void
    revolved_cell_state(const CellScratch &scratch,
                        const double      *committed,
                        const types::material_id id,
                        CellState<dim>    &state) const;

    /// Keeps in @p scratch the smallest det F at the corners of @p cell
    /// (of the displacement in @p scratch), where the Gauss points do not
    /// see a cell folded at a corner.
    void
    keep_corner_jacobian(const typename DoFHandler<dim>::active_cell_iterator &cell,
                         CellScratch                                          &scratch) const;

    /// The cell force (and matrix) of the responses in @p scratch (of the
    /// cell's kinematics).
    void
    cell_force_and_tangent(const bool mean_dilatation,
                           const bool with_tangent,
                           CellScratch &scratch) const;

    /// The same at finite strain, from F and S.
    void
    finite_strain_force_and_tangent(const bool with_tangent, CellScratch &scratch) const;

    /// The scratch of the cell kernels, made at the first call (its
    /// FEValues and their tables of the reference cell: a sizeable share
    /// of an evaluation on a small mesh) and kept; its smallest det F
    /// forgotten.
    CellScratch &
    fresh_scratch() const;

    /// Adds the cell force of @p scratch to @p force: by local row where
    /// @p force_values (CellMatrixPositions::local_values()) is given and
    /// the cell has positions, else through @p constraints.
    void
    add_cell_force(const unsigned int               active_cell_index,
                   const CellScratch               &scratch,
                   const AffineConstraints<double> &constraints,
                   Vector                          &force,
                   double *const                    force_values) const;

    /// Throws an InvertedCell on every rank if some rank's @p scratch met
    /// det F <= 0. Collective.
    void
    refuse_inverted_cells(const CellScratch &scratch) const;

    const ElasticBody<dim>  &body;
    const Materials<dim>    &materials;
    QuadratureHistory<dim>  &history;
    /// Of the last update_tangent(): the displacement (with ghost
    /// entries), and which cells added their elastic matrix (by active
    /// cell index).
    Vector                     tangent_at;
    std::vector<unsigned char> elastic_cells;
    /// Where update_tangent() adds the cell matrices that need no
    /// constraint.
    CellMatrixPositions<dim> positions;
    /// See element_force_norm().
    mutable double element_force_size = 0;
    /// See fresh_scratch().
    mutable std::unique_ptr<CellScratch> scratch;
    /// See new_mesh().
    ReferenceGradients<dim> reference;
  };
} // namespace FrictionalContact
