// SPDX-License-Identifier: GPL-3.0-or-later
//
// The ndda program: runs one scene described by a .prm file.

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <ndda/parameters/parameters.h>
#include <ndda/simulator.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <unistd.h>

namespace
{
  /**
   * OpenBLAS chooses its kernels when it is loaded, before main(): those
   * of OPENBLAS_CORETYPE if it is set, else those of the CPU. ndda.sh and
   * the test suite set OPENBLAS_CORETYPE=Haswell on every CPU with AVX2
   * and FMA, so that the results are the same to the bit on AMD and Intel
   * machines (CMakeLists.txt). A run of build/ndda started without it on
   * such a CPU starts itself again with it set, so that its results do
   * not depend on how it was started. Not under valgrind, which would not
   * follow the new program.
   */
  void
  start_again_with_openblas_kernels(char **argv)
  {
    if (std::getenv("OPENBLAS_CORETYPE") != nullptr)
      return;
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma"))
      return;
    const char *preload = std::getenv("LD_PRELOAD");
    if (preload != nullptr && std::strstr(preload, "valgrind") != nullptr)
      return;
    setenv("OPENBLAS_CORETYPE", "Haswell", 1);
    execv("/proc/self/exe", argv);
    // The run goes on with the kernels OpenBLAS chose.
    unsetenv("OPENBLAS_CORETYPE");
  }



  void
  print_help(std::ostream &out)
  {
    out << "ndda: nodal-based discontinuous deformation analysis on deal.II\n"
        << "\n"
        << "Usage:\n"
        << "  ndda scene.prm               run the scene\n"
        << "  ndda --resume output/<scene> continue a run from its last "
           "checkpoint\n"
        << "                               (Output/Checkpoint interval)\n"
        << "  ndda --validate scene.prm    check the scene (parameters, "
           "geometry,\n"
        << "                               mesh, points) and exit; writes "
           "nothing\n"
        << "  ndda --print-parameters      print every parameter with its "
           "documentation\n"
        << "  ndda --threads N ...         any of the above on N threads "
           "(default: every\n"
        << "                               core, or DEAL_II_NUM_THREADS); "
           "the results do not\n"
        << "                               depend on the number of threads "
           "(doc/design.md)\n"
        << "  mpirun -np N ndda scene.prm  run the scene on N MPI processes; "
           "with\n"
        << "                               Control/Linear solver = MUMPS or "
           "CG-AMG they\n"
        << "                               solve the linear systems together\n"
        << "  ndda --help                  this text\n"
        << "\n"
        << "Output goes to output/<scene name>/ unless Output/Directory "
           "says otherwise.\n";
  }

  void
  print_parameters(std::ostream &out)
  {
    // Declare with one example name in every name list, so that every kind
    // of subsection is documented.
    dealii::ParameterHandler                prm;
    ndda::parameters::Parameters::NameLists names;
    names.blocks              = {"<block name>"};
    names.regions             = {"<region name>"};
    names.materials           = {"<material name>"};
    names.point_loads         = {"<point load name>"};
    names.line_loads          = {"<line load name>"};
    names.boundary_conditions = {"<constraint name>"};
    names.bolts               = {"<bolt name>"};
    ndda::parameters::Parameters::declare_parameters(prm, names);
    prm.print_parameters(out, dealii::ParameterHandler::PRM);
  }
} // namespace



int
main(int argc, char **argv)
{
  start_again_with_openblas_kernels(argv);
  // Every core (or DEAL_II_NUM_THREADS) unless `--threads N`, divided
  // among the processes of this machine; the results do not depend on the
  // number of threads (ndda/base/threads.h).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(
    argc, argv, dealii::numbers::invalid_unsigned_int);
  unsigned int n_processes = 1;
  // On several processes a failure ends them all: one that fails alone
  // must not leave the others waiting for it.
  const auto failed = [&n_processes]() {
    if (n_processes > 1)
      MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  };
  try
    {
      // On several processes (mpirun -np N) every process runs the scene
      // and they solve its systems together (Simulator, LinearSolver);
      // only the first one speaks.
      n_processes = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        {
          std::cout.rdbuf(nullptr);
          std::cerr.rdbuf(nullptr);
        }

      std::vector<std::string> args(argv + 1, argv + argc);
      if (args.size() >= 1 && args[0] == "--threads")
        {
          unsigned int n_threads = 0;
          try
            {
              if (args.size() >= 2 &&
                  args[1].find_first_not_of("0123456789") == std::string::npos)
                n_threads = std::stoul(args[1]);
            }
          catch (const std::exception &)
            {
              n_threads = 0;
            }
          if (n_threads == 0)
            {
              std::cerr << "ndda: --threads needs a number of threads of 1 or "
                           "more, as in 'ndda --threads 2 scene.prm'.\n";
              return 1;
            }
          dealii::MultithreadInfo::set_thread_limit(n_threads);
          args.erase(args.begin(), args.begin() + 2);
        }
      if (args.empty() || args[0] == "--help" || args[0] == "-h")
        {
          print_help(std::cout);
          return args.empty() ? 1 : 0;
        }
      if (args[0] == "--print-parameters")
        {
          print_parameters(std::cout);
          return 0;
        }
      if (args[0] == "--validate")
        {
          if (args.size() != 2)
            {
              std::cerr << "ndda --validate needs one .prm file.\n";
              return 1;
            }
          ndda::Simulator<2> simulator(args[1]);
          simulator.setup();
          std::cout << "ndda: '" << args[1]
                    << "' is valid: " << simulator.get_mesh().n_blocks()
                    << " blocks, "
                    << simulator.get_mesh().get_triangulation().n_active_cells()
                    << " cells, " << simulator.get_dof_handler().n_dofs()
                    << " degrees of freedom.\n";
          return 0;
        }
      if (args[0] == "--resume")
        {
          if (args.size() != 2)
            {
              std::cerr << "ndda --resume needs one output directory.\n";
              return 1;
            }
          ndda::Simulator<2>::resume(args[1])->run();
          return 0;
        }
      if (args.size() != 1 || args[0].rfind("--", 0) == 0)
        {
          std::cerr << "ndda: unknown arguments. ";
          print_help(std::cerr);
          return 1;
        }
      ndda::Simulator<2> simulator(args[0]);
      simulator.run();
    }
  catch (const dealii::ExceptionBase &exc)
    {
      // ExcMessage carries the whole message; print it without deal.II's
      // file and line decoration.
      std::ostringstream info;
      exc.print_info(info);
      std::string message = info.str();
      message.erase(0, message.find_first_not_of(" \n\t"));
      std::cerr << "\nndda: error: " << message << std::endl;
      return failed();
    }
  catch (const std::exception &exc)
    {
      std::cerr << "\nndda: error: " << exc.what() << std::endl;
      return failed();
    }
  catch (...)
    {
      std::cerr << "\nndda: unknown error." << std::endl;
      return failed();
    }
  return 0;
}
