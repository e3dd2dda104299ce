#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/distributed/tria.h>

#include <frictional_contact/material/material.h>

#include <map>
#include <vector>

namespace FrictionalContact
{
  /**
   * The committed history of the material laws at the quadrature points of
   * the locally owned cells (for each cell, n_q x the values of its body's
   * law; none for laws without history), in deal.II's CellDataStorage.
   * The body evaluates its laws from it and commits the history of an
   * accepted increment into it; a failed or cut increment leaves it alone.
   * It moves with the cells through refinement, coarsening, repartitioning
   * and checkpoints (p4est's attached data): a child takes at all its
   * points the value of its parent's point that lies in it (the 2 x 2 (x 2)
   * Gauss points: one per child), and a parent's point takes the average
   * over the child it lies in. Piecewise constant, so a plastic zone keeps
   * its values without the overshoot of a smooth projection.
   */
  template <int dim>
  class QuadratureHistory
  {
  public:
    using CellIterator = typename Triangulation<dim>::cell_iterator;

    QuadratureHistory(const Materials<dim> &materials, const Quadrature<dim> &quadrature);

    /// Whether any body's law keeps history.
    bool
    active() const
    {
      return materials.max_history_values() > 0;
    }

    /// Zero history on every locally owned active cell of @p mesh.
    void
    reset(const parallel::distributed::Triangulation<dim> &mesh);

    /// The values of @p cell (n_q x the law's count, point by point), or
    /// nullptr if its law keeps none.
    double *
    values(const CellIterator &cell);

    const double *
    values(const CellIterator &cell) const;

    /// Attaches the history to the cells of @p mesh, before it is refined,
    /// repartitioned or saved.
    void
    attach(parallel::distributed::Triangulation<dim> &mesh);

    /// Forgets the attachment of a save() (which does not unpack).
    void
    clear_attachment()
    {
      handle = numbers::invalid_unsigned_int;
    }

    /// Bytes of the values of this rank's cells (what a checkpoint adds).
    std::size_t
    size_in_bytes() const;

    /// Takes the history from the cells of @p mesh, after it was refined
    /// or repartitioned (attach() before) or loaded (with the history of a
    /// checkpoint that had it).
    void
    unpack(parallel::distributed::Triangulation<dim> &mesh);

  private:
    struct CellValues
    {
      std::vector<double> values;
    };

    /// The values a cell of law @p id has.
    unsigned int
    n_values(const types::material_id id) const
    {
      return quadrature.size() * materials.history_size(id);
    }

    /// What a cell that changes passes on: its own values, or for a cell
    /// whose children are coarsened the average of each child at the
    /// point of the parent that lies in it.
    std::vector<char>
    pack(const CellIterator                                                    &cell,
         const typename parallel::distributed::Triangulation<dim>::CellStatus status) const;

    const Materials<dim> &materials;
    const Quadrature<dim> quadrature;
    /// For each child of a cell, the point of the parent that lies in it;
    /// for each point of the parent, the child it lies in.
    std::vector<unsigned int> parent_point_of_child;
    std::vector<unsigned int> child_of_parent_point;
    CellDataStorage<CellIterator, CellValues> storage;
    /// How many values the cells of this rank hold.
    std::size_t stored_values = 0;
    unsigned int handle = numbers::invalid_unsigned_int;
  };
} // namespace FrictionalContact
