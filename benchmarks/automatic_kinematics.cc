// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cost of Kinematics = auto (issue 15): prm/wall_impact.prm (198 bricks on
// a rigid base, a boulder strikes the top at 5.4 m/s, 0.3 s) with every
// brick and the boulder meshed, affine, or auto; the runs alternate, so
// that the machine's drift touches them alike. For each model: the mean
// wall time of a run and per step, steps (with cuts), factorizations,
// and the ratio to the meshed run; for auto also the promotions and the
// most blocks meshed at once.
//
// Usage: automatic_kinematics [rounds]   (default 2; a round is ~1 min)

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <ndda/parameters/parameters.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

namespace
{
  /** prm/wall_impact.prm with Control/Kinematics = @p model, no output. */
  std::string
  scene(const std::string &model)
  {
    std::ifstream file(std::string(NDDA_SOURCE_DIR) + "/prm/wall_impact.prm");
    std::stringstream text;
    text << file.rdbuf();
    std::string       s     = text.str();
    const std::string entry = "set Kinematics      = auto";
    if (s.find(entry) == std::string::npos)
      {
        std::cerr << "prm/wall_impact.prm: no '" << entry << "'" << std::endl;
        std::exit(1);
      }
    s.replace(s.find(entry), entry.size(), "set Kinematics = " + model);
    s.replace(s.find("set Interval"),
              std::string("set Interval").size(),
              "set Write vtu = false\n  set Interval");
    return s;
  }

  struct Figures
  {
    double       seconds = 0;
    unsigned int steps = 0, cuts = 0, factorizations = 0, promotions = 0,
                 most_meshed = 0;
  };

  Figures
  run(const std::string &model)
  {
    dealii::ParameterHandler     prm;
    ndda::parameters::Parameters parameters;
    parameters.read(scene(model), "wall_impact.prm", prm);
    ndda::Simulator<2> simulator(parameters);
    Figures            f;
    const auto         start = std::chrono::steady_clock::now();
    simulator.setup();
    while (simulator.get_time() < parameters.control.end_time - 1e-12)
      {
        simulator.do_time_step();
        f.cuts += simulator.get_step_report().cuts;
        const auto meshed = simulator.get_discretization().meshed_blocks();
        f.most_meshed     = std::max<unsigned int>(
          f.most_meshed, std::count(meshed.begin(), meshed.end(), true));
      }
    f.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    f.steps          = simulator.get_step_number();
    f.factorizations = simulator.n_factorizations();
    f.promotions     = simulator.get_automatic_kinematics().n_promotions();
    return f;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int             rounds = argc > 1 ? std::atoi(argv[1]) : 2;
  const std::vector<std::string> models = {"meshed", "affine", "auto"};
  std::map<std::string, Figures> total;
  for (unsigned int r = 0; r < rounds; ++r)
    for (const auto &model : models)
      {
        const Figures f = run(model);
        std::cout << "round " << r + 1 << " " << model << ": " << f.seconds
                  << " s" << std::endl;
        Figures &t = total[model];
        t.seconds += f.seconds / rounds;
        t = {t.seconds,
             f.steps,
             f.cuts,
             f.factorizations,
             f.promotions,
             f.most_meshed};
      }
  std::cout << "\n| model | s per run | ms per step | steps (cuts) | "
               "factorizations per step | promotions | most meshed | cost "
               "against meshed |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto &model : models)
    {
      const Figures &t = total[model];
      std::cout << std::setprecision(3) << "| " << model << " | " << t.seconds
                << " | " << 1e3 * t.seconds / t.steps << " | " << t.steps
                << " (" << t.cuts << ") | "
                << double(t.factorizations) / t.steps << " | " << t.promotions
                << " | " << t.most_meshed << " | "
                << t.seconds / total["meshed"].seconds << " |" << std::endl;
    }
}
