// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_parallel_shared_mesh_h
#define ndda_parallel_shared_mesh_h

#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <memory>
#include <vector>

namespace ndda
{
  using namespace dealii;

  /**
   * @name The scene's triangulation on several MPI processes
   *
   * One process holds a plain Triangulation. On several, every process
   * holds the whole mesh as deal.II's parallel::shared::Triangulation
   * (doc/design.md, "MPI"), which gives each active cell an owner: the
   * cells of process p are the contiguous range of active cell indices
   * [p n / P, (p + 1) n / P) of OwnedCells (the cells are numbered along a
   * Hilbert curve, so that a range is a compact piece of the scene), set
   * whenever the mesh is created or refined. What deal.II does
   * differently on a shared triangulation is undone or avoided where ndda
   * needs the whole mesh on every process:
   *
   * - DoFHandler::distribute_dofs() numbers the dofs subdomain by
   *   subdomain; number_dofs_as_on_one_process() gives them back the
   *   numbers one process gives them, so that every sum over dofs, and
   *   with it the round-off, is the same on any number of processes;
   * - DoFTools::make_sparsity_pattern() visits only the locally owned
   *   cells; make_whole_sparsity_pattern() visits all.
   *
   * DataOut visits the locally owned cells by default: each process
   * writes the patches of its own cells.
   *
   * @ingroup parallel
   */
  /** @{ */

  /**
   * The triangulation for a scene run on the processes of
   * @p communicator: a plain Triangulation on one process (or without
   * MPI), else a parallel::shared::Triangulation that gives process p the
   * cells of OwnedCells. Every process must create its mesh alike.
   */
  std::unique_ptr<Triangulation<2>>
  make_scene_triangulation(const MPI_Comm communicator);

  /** Whether @p triangulation is shared among more than one process. */
  bool
  is_shared(const Triangulation<2> &triangulation);

  /**
   * Renumber the dofs of @p dof_handler as distribute_dofs() numbers them
   * on one process: in the order in which a walk over the active cells,
   * each cell's dofs in their local order, first meets them. Does nothing
   * unless the triangulation is_shared(). Collective.
   */
  void
  number_dofs_as_on_one_process(DoFHandler<2> &dof_handler);

  /**
   * The process that owns each dof of @p dof_handler
   * (DoFHandler::locally_owned_dofs() of every process); all 0 unless the
   * triangulation is_shared(). Collective.
   */
  std::vector<unsigned int>
  dof_owners(const DoFHandler<2> &dof_handler);

  /**
   * Add the couplings of every active cell's dofs to @p pattern (through
   * @p constraints, keeping the constrained dofs' entries), whoever owns
   * the cell: DoFTools::make_sparsity_pattern() for a mesh every process
   * holds whole.
   */
  void
  make_whole_sparsity_pattern(
    const DoFHandler<2>             &dof_handler,
    DynamicSparsityPattern          &pattern,
    const AffineConstraints<double> &constraints = AffineConstraints<double>());

  /** @} */
} // namespace ndda

#endif
