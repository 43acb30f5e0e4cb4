// SPDX-License-Identifier: GPL-3.0-or-later
#include <ndda/parallel/owned_cells.h>
#include <ndda/parallel/shared_mesh.h>

#include <algorithm>
#include <climits>
#include <string>

namespace ndda
{
  namespace
  {
    /** @p end, the end of a process's values in a gathered array, as
     * the int that MPI counts in. */
    int
    mpi_count(const std::size_t end)
    {
      AssertThrow(end <= std::size_t(INT_MAX),
                  ExcMessage("OwnedCells: more than 2^31 values (or bytes) "
                             "to send in one call (" +
                             std::to_string(end) + ")."));
      return end;
    }
  } // namespace



  void
  OwnedCells::check_size(const unsigned int n_cells,
                         const std::string &what) const
  {
    AssertThrow(!is_split() || this->n_cells() == n_cells,
                ExcMessage(what +
                           ": the cells are split among the "
                           "processes as " +
                           std::to_string(this->n_cells()) + " cells, " +
                           std::to_string(n_cells) + " are given."));
  }



  void
  OwnedCells::set_communicator(const MPI_Comm communicator)
  {
    const bool with_mpi = Utilities::MPI::job_supports_mpi();
    this->communicator  = with_mpi ? communicator : MPI_COMM_SELF;
    this_process =
      with_mpi ? Utilities::MPI::this_mpi_process(this->communicator) : 0;
    const unsigned int n_processes =
      with_mpi ? Utilities::MPI::n_mpi_processes(this->communicator) : 1;
    first_cell.assign(n_processes + 1, 0);
  }



  void
  OwnedCells::reinit(const unsigned int n_cells)
  {
    const unsigned int n_processes = first_cell.size() - 1;
    for (unsigned int p = 0; p <= n_processes; ++p)
      first_cell[p] = first_cell_of(p, n_cells, n_processes);
  }



  void
  OwnedCells::reinit(const Triangulation<2> &triangulation)
  {
    const unsigned int n_cells     = triangulation.n_active_cells();
    const unsigned int n_processes = first_cell.size() - 1;
    if (!is_shared(triangulation))
      {
        reinit(n_cells);
        return;
      }
    AssertThrow(Utilities::MPI::n_mpi_processes(
                  triangulation.get_communicator()) == n_processes,
                ExcMessage("OwnedCells: the triangulation is shared among " +
                           std::to_string(Utilities::MPI::n_mpi_processes(
                             triangulation.get_communicator())) +
                           " processes, the cells are to be split among " +
                           std::to_string(n_processes) + "."));
    // The owners' ranges, in process order; an owner that comes back
    // after another's cells has no range.
    first_cell.assign(n_processes + 1, 0);
    unsigned int owner = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const auto c = cell->active_cell_index();
        const auto s = cell->subdomain_id();
        AssertThrow(s >= owner && s < n_processes,
                    ExcMessage("OwnedCells: the owners of the cells do not "
                               "hold contiguous ranges in process order "
                               "(cell " +
                               std::to_string(c) + " belongs to process " +
                               std::to_string(s) +
                               ", after cells of "
                               "process " +
                               std::to_string(owner) + ")."));
        for (; owner < s; ++owner)
          first_cell[owner + 1] = c;
      }
    for (; owner < n_processes; ++owner)
      first_cell[owner + 1] = n_cells;
  }



  std::vector<bool>
  OwnedCells::owned_vertices(const std::vector<unsigned int> &cell_vertices,
                             const unsigned int               per_cell,
                             const unsigned int               n_vertices) const
  {
    AssertThrow(per_cell > 0 &&
                  cell_vertices.size() == std::size_t(n_cells()) * per_cell,
                ExcMessage("OwnedCells::owned_vertices(): the cells are "
                           "split as " +
                           std::to_string(n_cells()) + " cells, " +
                           std::to_string(cell_vertices.size()) +
                           " vertex indices are given for " +
                           std::to_string(per_cell) + " per cell."));
    std::vector<bool> seen(n_vertices, false);
    std::vector<bool> owned(n_vertices, false);
    for (unsigned int c = 0; c < end(); ++c)
      for (unsigned int k = 0; k < per_cell; ++k)
        {
          const unsigned int v = cell_vertices[std::size_t(c) * per_cell + k];
          AssertIndexRange(v, n_vertices);
          if (!seen[v])
            {
              seen[v]  = true;
              owned[v] = c >= begin();
            }
        }
    return owned;
  }



  std::vector<char>
  OwnedCells::gather_bytes(const char *mine, const std::size_t n_bytes) const
  {
    const std::size_t n_processes = first_cell.size() - 1;
    const int         count       = mpi_count(n_bytes);
    std::vector<int>  counts(n_processes);
    int               error = MPI_Allgather(
      &count, 1, MPI_INT, counts.data(), 1, MPI_INT, communicator);
    AssertThrowMPI(error);
    std::vector<int> offsets(n_processes);
    std::size_t      total = 0;
    for (std::size_t p = 0; p < n_processes; ++p)
      {
        offsets[p] = mpi_count(total);
        total += counts[p];
      }
    mpi_count(total);
    std::vector<char> all(total);
    error = MPI_Allgatherv(mine,
                           count,
                           MPI_BYTE,
                           all.data(),
                           counts.data(),
                           offsets.data(),
                           MPI_BYTE,
                           communicator);
    AssertThrowMPI(error);
    return all;
  }



  void
  OwnedCells::share_doubles(double *values, const std::size_t per_cell) const
  {
    const std::size_t n_processes = first_cell.size() - 1;
    std::vector<int>  counts(n_processes);
    std::vector<int>  offsets(n_processes);
    for (std::size_t p = 0; p < n_processes; ++p)
      {
        const std::size_t count =
          std::size_t(first_cell[p + 1] - first_cell[p]) * per_cell;
        const std::size_t offset = std::size_t(first_cell[p]) * per_cell;
        counts[p]                = mpi_count(offset + count) - offset;
        offsets[p]               = offset;
      }
    const int error = MPI_Allgatherv(MPI_IN_PLACE,
                                     0,
                                     MPI_DATATYPE_NULL,
                                     values,
                                     counts.data(),
                                     offsets.data(),
                                     MPI_DOUBLE,
                                     communicator);
    AssertThrowMPI(error);
  }



  void
  OwnedCells::share_doubles(double                          *values,
                            const std::size_t                per_cell,
                            const std::vector<unsigned int> &cells) const
  {
    // Each process's cells of the list, packed in list order, gathered
    // by all, and unpacked where they belong.
    const std::size_t n_processes = first_cell.size() - 1;
    std::vector<std::vector<unsigned int>::const_iterator> start(n_processes +
                                                                 1);
    for (std::size_t p = 0; p <= n_processes; ++p)
      start[p] = std::lower_bound(cells.begin(), cells.end(), first_cell[p]);
    std::vector<int> counts(n_processes);
    std::vector<int> offsets(n_processes);
    std::size_t      total = 0;
    for (std::size_t p = 0; p < n_processes; ++p)
      {
        const std::size_t count = (start[p + 1] - start[p]) * per_cell;
        counts[p]               = mpi_count(total + count) - total;
        offsets[p]              = total;
        total += count;
      }
    std::vector<double> own;
    own.reserve(counts[this_process]);
    for (auto c = start[this_process]; c != start[this_process + 1]; ++c)
      own.insert(own.end(),
                 values + std::size_t(*c) * per_cell,
                 values + std::size_t(*c + 1) * per_cell);
    std::vector<double> all(total);
    const int           error = MPI_Allgatherv(own.data(),
                                     counts[this_process],
                                     MPI_DOUBLE,
                                     all.data(),
                                     counts.data(),
                                     offsets.data(),
                                     MPI_DOUBLE,
                                     communicator);
    AssertThrowMPI(error);
    for (std::size_t p = 0; p < n_processes; ++p)
      if (p != this_process)
        {
          const double *from = all.data() + offsets[p];
          for (auto c = start[p]; c != start[p + 1]; ++c, from += per_cell)
            std::copy(from,
                      from + per_cell,
                      values + std::size_t(*c) * per_cell);
        }
  }
} // namespace ndda
