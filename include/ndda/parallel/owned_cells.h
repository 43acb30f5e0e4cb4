// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_parallel_owned_cells_h
#define ndda_parallel_owned_cells_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <deal.II/grid/tria.h>

#include <cstddef>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace ndda
{
  using namespace dealii;

  /**
   * The active cells of a scene split among the processes of an MPI
   * communicator, for the work that is done cell by cell: each process
   * owns a contiguous range of cells (the cells are numbered along a
   * Hilbert curve, so that a range is a compact part of the scene), does
   * the work of those cells only, and share() then gives every process the
   * results of every cell.
   *
   * Every process holds the whole scene (doc/design.md, "MPI"), and sums
   * over cells are taken on every process alike in cell order from the
   * shared per-cell results. A cell's result does not depend on the
   * process that computes it, so a run on any number of processes gives
   * the same results to the last bit as a run on one.
   *
   * With one process (or MPI_COMM_SELF) it owns every cell and share()
   * does nothing.
   *
   * @ingroup parallel
   */
  class OwnedCells
  {
  public:
    /** Split among the processes of @p communicator (not duplicated: the
     * owner of the communicator keeps it alive). */
    void
    set_communicator(const MPI_Comm communicator);

    /** Split @p n_cells cells into ranges as equal as they can be:
     * process p owns the cells [first_cell_of(p), first_cell_of(p + 1)). */
    void
    reinit(const unsigned int n_cells);

    /**
     * Split the active cells of @p triangulation among the processes: as
     * its owners say if it is a parallel::shared::Triangulation on the
     * processes of the communicator (make_scene_triangulation() gives each
     * the range of reinit()), else as reinit(n_active_cells). Throws if
     * the owners do not hold contiguous ranges in process order.
     */
    void
    reinit(const Triangulation<2> &triangulation);

    /** The first of @p n_cells cells that process @p p of @p n_processes
     * owns: p n / P, rounded down. */
    static unsigned int
    first_cell_of(const unsigned int p,
                  const unsigned int n_cells,
                  const unsigned int n_processes)
    {
      return (std::size_t(n_cells) * p) / n_processes;
    }

    /** The number of cells split. */
    unsigned int
    n_cells() const
    {
      return first_cell.back();
    }

    /** The first cell of this process. */
    unsigned int
    begin() const
    {
      return first_cell[this_process];
    }

    /** One past the last cell of this process. */
    unsigned int
    end() const
    {
      return first_cell[this_process + 1];
    }

    /** Throw unless the cells are split as @p n_cells cells (or not
     * split); @p what names the caller in the message. */
    void
    check_size(const unsigned int n_cells, const std::string &what) const;

    /** Whether the cells are split among more than one process. */
    bool
    is_split() const
    {
      return first_cell.size() > 2;
    }

    /**
     * Give every process every cell's values of @p values, which holds
     * @p per_cell values of each cell, cell after cell, of which this
     * process has set those of its own cells. The values are sent as they
     * are in memory: T must be trivially copyable and a whole number of
     * doubles (as a double, a Tensor or a SymmetricTensor of doubles is).
     * Collective.
     */
    template <typename T>
    void
    share(std::vector<T> &values, const std::size_t per_cell) const;

    /**
     * share() for the cells @p cells only (in increasing order, the same
     * list on every process): every process gets the values of those
     * cells that other processes own; the values of other cells stay as
     * they are. Collective.
     */
    template <typename T>
    void
    share(std::vector<T>                  &values,
          const std::size_t                per_cell,
          const std::vector<unsigned int> &cells) const;

    /**
     * The vertices this process owns, by vertex index: those whose first
     * cell (the lowest-numbered active cell at the vertex) is its own, so
     * that every vertex of a cell has one owner. @p cell_vertices holds
     * the vertices of every cell, @p per_cell of them, cell after cell
     * (DofMap::cell_vertices); there are @p n_vertices vertices, and one
     * that is no cell's vertex is no process's.
     */
    std::vector<bool>
    owned_vertices(const std::vector<unsigned int> &cell_vertices,
                   const unsigned int               per_cell,
                   const unsigned int               n_vertices) const;

    /**
     * Every process's list @p mine, joined in process order, on every
     * process. The values are sent as they are in memory: T must be
     * trivially copyable. Collective.
     */
    template <typename T>
    std::vector<T>
    gather(const std::vector<T> &mine) const;

  private:
    /** gather() on @p n_bytes bytes at @p mine. */
    std::vector<char>
    gather_bytes(const char *mine, const std::size_t n_bytes) const;

    /** share() on @p values, @p per_cell doubles per cell. */
    void
    share_doubles(double *values, const std::size_t per_cell) const;

    /** share() on @p values, @p per_cell doubles per cell, of @p cells. */
    void
    share_doubles(double                          *values,
                  const std::size_t                per_cell,
                  const std::vector<unsigned int> &cells) const;

    MPI_Comm     communicator = MPI_COMM_SELF;
    unsigned int this_process = 0;
    /// The first cell of each process, and the number of cells at the end.
    std::vector<unsigned int> first_cell = {0, 0};
  };



  template <typename T>
  void
  OwnedCells::share(std::vector<T> &values, const std::size_t per_cell) const
  {
    static_assert(std::is_trivially_copyable_v<T> &&
                    sizeof(T) % sizeof(double) == 0,
                  "OwnedCells::share() sends whole doubles.");
    if (!is_split())
      return;
    AssertThrow(values.size() == std::size_t(n_cells()) * per_cell,
                ExcDimensionMismatch(values.size(),
                                     std::size_t(n_cells()) * per_cell));
    share_doubles(reinterpret_cast<double *>(values.data()),
                  per_cell * (sizeof(T) / sizeof(double)));
  }



  template <typename T>
  void
  OwnedCells::share(std::vector<T>                  &values,
                    const std::size_t                per_cell,
                    const std::vector<unsigned int> &cells) const
  {
    static_assert(std::is_trivially_copyable_v<T> &&
                    sizeof(T) % sizeof(double) == 0,
                  "OwnedCells::share() sends whole doubles.");
    if (!is_split())
      return;
    if (cells.size() == n_cells())
      share(values, per_cell);
    else
      {
        AssertThrow(values.size() == std::size_t(n_cells()) * per_cell,
                    ExcDimensionMismatch(values.size(),
                                         std::size_t(n_cells()) * per_cell));
        share_doubles(reinterpret_cast<double *>(values.data()),
                      per_cell * (sizeof(T) / sizeof(double)),
                      cells);
      }
  }


  template <typename T>
  std::vector<T>
  OwnedCells::gather(const std::vector<T> &mine) const
  {
    static_assert(std::is_trivially_copyable_v<T>,
                  "OwnedCells::gather() sends the bytes of the values.");
    if (!is_split())
      return mine;
    const std::vector<char> bytes =
      gather_bytes(reinterpret_cast<const char *>(mine.data()),
                   mine.size() * sizeof(T));
    std::vector<T> all(bytes.size() / sizeof(T));
    if (!all.empty())
      std::memcpy(static_cast<void *>(all.data()), bytes.data(), bytes.size());
    return all;
  }
} // namespace ndda

#endif
