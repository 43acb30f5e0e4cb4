// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>

#include <ndda/parallel/serial_work.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <sched.h>
#include <sstream>
#include <string>
#include <thread>

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
    AssertThrowMPI(MPI_Comm_free(&machine));
    // No more threads than the cores the first process may run on: an
    // MPI launcher that binds each process to a core (Open MPI does so
    // by default for two processes; `mpirun --bind-to none` does not)
    // leaves it one.
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    const unsigned int n_allowed =
      sched_getaffinity(0, sizeof(allowed), &allowed) == 0 ?
        CPU_COUNT(&allowed) :
        1;
    const unsigned int own_threads = MultithreadInfo::n_threads();
    n_on_machine =
      this_process == 0 ?
        std::max(1u, std::min(on_machine, n_allowed / own_threads)) :
        1;
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
        const unsigned int own_threads = MultithreadInfo::n_threads();
        if (n_on_machine > 1)
          MultithreadInfo::set_thread_limit(own_threads * n_on_machine);
        try
          {
            work();
          }
        catch (...)
          {
            error = message_of_current_exception();
          }
        if (n_on_machine > 1)
          MultithreadInfo::set_thread_limit(own_threads);
      }
    wait_without_spinning(communicator);
    error = Utilities::MPI::broadcast(communicator, error, 0);
    AssertThrow(error.empty(), ExcMessage(error));
  }
} // namespace ndda
