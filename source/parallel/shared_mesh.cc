// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/distributed/shared_tria.h>

#include <ndda/parallel/owned_cells.h>
#include <ndda/parallel/shared_mesh.h>

#include <algorithm>
#include <string>
#include <vector>

namespace ndda
{
  namespace
  {
    /** Give the active cells of @p triangulation the owners of
     * OwnedCells::reinit(). */
    void
    assign_owners(Triangulation<2> &triangulation, const unsigned n_processes)
    {
      const unsigned int n_cells = triangulation.n_active_cells();
      unsigned int       owner   = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          const unsigned int c = cell->active_cell_index();
          while (c >=
                 OwnedCells::first_cell_of(owner + 1, n_cells, n_processes))
            ++owner;
          cell->set_subdomain_id(owner);
        }
    }
  } // namespace



  std::unique_ptr<Triangulation<2>>
  make_scene_triangulation(const MPI_Comm communicator)
  {
    const unsigned int n_processes =
      Utilities::MPI::job_supports_mpi() ?
        Utilities::MPI::n_mpi_processes(communicator) :
        1;
    if (n_processes == 1)
      return std::make_unique<Triangulation<2>>();
    // The owners are set when deal.II has made or refined the cells and
    // before it counts them (partition_custom_signal).
    auto triangulation = std::make_unique<parallel::shared::Triangulation<2>>(
      communicator,
      Triangulation<2>::none,
      false,
      parallel::shared::Triangulation<2>::partition_custom_signal);
    auto *const tria = triangulation.get();
    tria->signals.create.connect(
      [tria, n_processes]() { assign_owners(*tria, n_processes); });
    tria->signals.post_refinement.connect(
      [tria, n_processes]() { assign_owners(*tria, n_processes); });
    return triangulation;
  }



  bool
  is_shared(const Triangulation<2> &triangulation)
  {
    const auto *shared =
      dynamic_cast<const parallel::shared::Triangulation<2> *>(&triangulation);
    return shared != nullptr &&
           Utilities::MPI::n_mpi_processes(shared->get_communicator()) > 1;
  }



  void
  number_dofs_as_on_one_process(DoFHandler<2> &dof_handler)
  {
    if (!is_shared(dof_handler.get_triangulation()))
      return;
    // deal.II numbers the dofs on one process in this walk, and on a
    // shared triangulation then sorts them by owner, stably
    // (dof_handler_policy.cc, 9.4); the walk finds the first numbers again.
    const auto                           n_dofs = dof_handler.n_dofs();
    std::vector<types::global_dof_index> new_numbers(
      n_dofs, numbers::invalid_dof_index);
    std::vector<types::global_dof_index> dofs;
    types::global_dof_index              next = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        dofs.resize(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (const auto i : dofs)
          if (new_numbers[i] == numbers::invalid_dof_index)
            new_numbers[i] = next++;
      }
    AssertThrow(next == n_dofs,
                ExcMessage("number_dofs_as_on_one_process(): the cells hold " +
                           std::to_string(next) + " of the " +
                           std::to_string(n_dofs) + " dofs."));
    dof_handler.renumber_dofs(new_numbers);
  }



  std::vector<unsigned int>
  dof_owners(const DoFHandler<2> &dof_handler)
  {
    std::vector<unsigned int> owner(dof_handler.n_dofs(), 0);
    if (!is_shared(dof_handler.get_triangulation()))
      return owner;
    const std::vector<IndexSet> owned = Utilities::MPI::all_gather(
      dof_handler.get_triangulation().get_communicator(),
      dof_handler.locally_owned_dofs());
    std::vector<bool> seen(owner.size(), false);
    for (unsigned int p = 0; p < owned.size(); ++p)
      for (const auto i : owned[p])
        {
          AssertThrow(!seen[i], ExcInternalError());
          seen[i]  = true;
          owner[i] = p;
        }
    AssertThrow(std::find(seen.begin(), seen.end(), false) == seen.end(),
                ExcInternalError());
    return owner;
  }



  void
  make_whole_sparsity_pattern(const DoFHandler<2>             &dof_handler,
                              DynamicSparsityPattern          &pattern,
                              const AffineConstraints<double> &constraints)
  {
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        dofs.resize(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        constraints.add_entries_local_to_global(dofs, pattern, true);
      }
  }
} // namespace ndda
