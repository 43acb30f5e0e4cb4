// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>

#include <ndda/parallel/serial_work.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <dirent.h>
#include <sched.h>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace ndda
{
  namespace
  {
    /**
     * Wait at a barrier of @p communicator without spinning: poll it, and
     * sleep a tenth of the time waited so far between polls (20 us to
     * 1 ms).
     */
    void
    wait_without_spinning(const MPI_Comm communicator)
    {
      using Clock = std::chrono::steady_clock;
      MPI_Request request;
      AssertThrowMPI(MPI_Ibarrier(communicator, &request));
      int done = 0;
      AssertThrowMPI(MPI_Test(&request, &done, MPI_STATUS_IGNORE));
      const auto start = Clock::now();
      while (!done)
        {
          const auto waited =
            std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() -
                                                                  start);
          std::this_thread::sleep_for(
            std::clamp(waited / 10,
                       std::chrono::microseconds(20),
                       std::chrono::microseconds(1000)));
          AssertThrowMPI(MPI_Test(&request, &done, MPI_STATUS_IGNORE));
        }
    }



    /** The threads of this process, each with the cores it may run on. */
    std::vector<std::pair<pid_t, cpu_set_t>>
    cores_of_threads()
    {
      std::vector<std::pair<pid_t, cpu_set_t>> threads;
      DIR *const directory = opendir("/proc/self/task");
      if (directory == nullptr)
        return threads;
      while (const dirent *entry = readdir(directory))
        {
          if (entry->d_name[0] == '.')
            continue;
          const pid_t thread = std::atoi(entry->d_name);
          cpu_set_t   cores;
          CPU_ZERO(&cores);
          if (sched_getaffinity(thread, sizeof(cores), &cores) == 0)
            threads.emplace_back(thread, cores);
        }
      closedir(directory);
      return threads;
    }



    /**
     * Let every thread of this process run on @p cores (a thread that has
     * ended meanwhile is skipped), and return the cores each had.
     */
    std::vector<std::pair<pid_t, cpu_set_t>>
    widen_cores(const cpu_set_t &cores)
    {
      const auto before = cores_of_threads();
      for (const auto &thread : before)
        sched_setaffinity(thread.first, sizeof(cores), &cores);
      return before;
    }



    /**
     * Give every thread of this process back the cores it had @p before;
     * threads started since get @p own, the calling thread's.
     */
    void
    restore_cores(const std::vector<std::pair<pid_t, cpu_set_t>> &before,
                  const cpu_set_t                                &own)
    {
      for (const auto &thread : cores_of_threads())
        {
          const auto had =
            std::find_if(before.begin(), before.end(), [&](const auto &t) {
              return t.first == thread.first;
            });
          const cpu_set_t &cores = had != before.end() ? had->second : own;
          sched_setaffinity(thread.first, sizeof(cores), &cores);
        }
    }



    /** The message of the exception in flight (call in a catch block),
     * without deal.II's indentation. */
    std::string
    message_of_current_exception()
    {
      std::string error;
      try
        {
          throw;
        }
      catch (const ExceptionBase &exc)
        {
          std::ostringstream message;
          exc.print_info(message);
          error = message.str();
        }
      catch (const std::exception &exc)
        {
          error = exc.what();
        }
      catch (...)
        {}
      error.erase(0, error.find_first_not_of(" \n\t"));
      while (!error.empty() && std::isspace(error.back()))
        error.pop_back();
      return error.empty() ? "unknown error" : error;
    }
  } // namespace



  SerialWork::SerialWork(const MPI_Comm communicator)
  {
    CPU_ZERO(&machine_cores);
    if (!Utilities::MPI::job_supports_mpi())
      return;
    this->communicator = communicator;
    n_processes        = Utilities::MPI::n_mpi_processes(communicator);
    this_process       = Utilities::MPI::this_mpi_process(communicator);
    if (n_processes == 1)
      return;
    // The processes that share the first process's machine (its memory).
    MPI_Comm machine;
    AssertThrowMPI(MPI_Comm_split_type(
      communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &machine));
    const unsigned int on_machine = Utilities::MPI::n_mpi_processes(machine);
    // The cores of all of them: an MPI launcher may bind each process to
    // cores of its own (Open MPI does so by default for two processes;
    // `mpirun --bind-to none` does not).
    cpu_set_t own;
    CPU_ZERO(&own);
    if (sched_getaffinity(0, sizeof(own), &own) != 0)
      CPU_SET(sched_getcpu() >= 0 ? sched_getcpu() : 0, &own);
    std::vector<cpu_set_t> cores(on_machine);
    AssertThrowMPI(MPI_Allgather(&own,
                                 sizeof(cpu_set_t),
                                 MPI_BYTE,
                                 cores.data(),
                                 sizeof(cpu_set_t),
                                 MPI_BYTE,
                                 machine));
    AssertThrowMPI(MPI_Comm_free(&machine));
    for (const auto &c : cores)
      CPU_OR(&machine_cores, &machine_cores, &c);
    // No more threads than those cores.
    const unsigned int own_threads = MultithreadInfo::n_threads();
    n_on_machine                   = this_process == 0 ?
                                       std::max(1u,
                              std::min<unsigned int>(on_machine,
                                                     CPU_COUNT(&machine_cores) /
                                                       own_threads)) :
                                       1;
    if (n_on_machine > 1)
      arena = std::make_unique<tbb::task_arena>(own_threads * n_on_machine);
  }



  void
  SerialWork::run(const std::function<void()> &work) const
  {
    if (n_processes == 1)
      {
        work();
        return;
      }
    std::string error;
    if (this_process == 0)
      {
        const auto run_work = [&]() {
          try
            {
              work();
            }
          catch (...)
            {
              error = message_of_current_exception();
            }
        };
        if (n_on_machine == 1)
          run_work();
        else
          {
            // Every thread on the cores of the machine's processes, and an
            // arena of their threads: TBB's own arena keeps the number of
            // cores the process had when it began.
            cpu_set_t own;
            CPU_ZERO(&own);
            const bool widen = sched_getaffinity(0, sizeof(own), &own) == 0 &&
                               !CPU_EQUAL(&own, &machine_cores);
            std::vector<std::pair<pid_t, cpu_set_t>> before;
            if (widen)
              before = widen_cores(machine_cores);
            const unsigned int own_threads = MultithreadInfo::n_threads();
            MultithreadInfo::set_thread_limit(own_threads * n_on_machine);
            arena->execute(run_work);
            MultithreadInfo::set_thread_limit(own_threads);
            if (widen)
              restore_cores(before, own);
          }
      }
    wait_without_spinning(communicator);
    error = Utilities::MPI::broadcast(communicator, error, 0);
    AssertThrow(error.empty(), ExcMessage(error));
  }
} // namespace ndda
