// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_parallel_serial_work_h
#define ndda_parallel_serial_work_h

#include <deal.II/base/mpi.h>

#include <functional>
#include <memory>
#include <sched.h>
#include <tbb/task_arena.h>

namespace ndda
{
  using namespace dealii;

  /**
   * Work that the first process of a communicator does alone while the
   * others wait for its result: the serial linear solvers on several
   * processes (doc/design.md, "MPI").
   *
   * - The others wait without spinning: they poll a non-blocking barrier
   *   and sleep in between, each time a tenth of the time they have waited
   *   so far (20 us to 1 ms), so that they leave their cores to the first
   *   process and wake at most about a tenth of the wait late. (Open MPI's
   *   blocking calls poll without pause and keep a core busy.)
   * - The first process does the work on the threads and the cores of
   *   every process on its machine: its own number of threads times the
   *   number of processes there (at most as many as those processes' cores
   *   together), in a TBB arena of that many threads. An MPI launcher that
   *   binds each process to its own cores (Open MPI does so by default for
   *   up to two processes) would leave it its own cores only, so for the
   *   work every thread of the first process may run on the cores of all
   *   the processes on its machine; afterwards each thread gets back the
   *   cores it had, and the process its own number of threads. ndda's
   *   results do not depend on the number of threads, so the work gives
   *   the same bits.
   * - If the work throws on the first process, every process throws the
   *   same message.
   *
   * With one process it only runs the work.
   *
   * @ingroup parallel
   */
  class SerialWork
  {
  public:
    /** For the processes of @p communicator (not duplicated). Collective. */
    explicit SerialWork(const MPI_Comm communicator = MPI_COMM_SELF);

    /** Run @p work on the first process, as the class says. Collective. */
    void
    run(const std::function<void()> &work) const;

    /** The number of processes on the first process's machine whose
     * threads it takes, at most as many as their cores allow (1 with one
     * process, and on the other processes). */
    unsigned int
    processes_on_first_machine() const
    {
      return n_on_machine;
    }

  private:
    MPI_Comm     communicator = MPI_COMM_SELF;
    unsigned int n_processes  = 1;
    unsigned int this_process = 0;
    unsigned int n_on_machine = 1;
    /// The first process: the cores of the processes on its machine.
    cpu_set_t machine_cores;
    /// The first process, with processes on its machine to take from: an
    /// arena of their threads.
    std::unique_ptr<tbb::task_arena> arena;
  };
} // namespace ndda

#endif
