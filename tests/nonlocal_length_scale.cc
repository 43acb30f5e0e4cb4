// SPDX-License-Identifier: GPL-3.0-or-later
//
// A length scale for crack initiation (issue 18): with 'Edge stress =
// nonlocal average' the first failure time and the first crack load
// converge as the mesh is refined; with the thesis's cell average they do
// not where the stress is singular.
//
// Two scenes, each on the meshes h and h/2, with the cell average and with
// the nonlocal average over the radius R:
//  - prm/inclined_crack_tension.prm (a 42 mm crack at 45 degrees in a
//    100 mm square pulled at its top; Mohr-Coulomb, Table 2): h = 2.5 mm
//    and 1.25 mm, R = 7.5 mm. The stress at the crack's tips is singular
//    (1/sqrt(r)): the cell-average first failure time falls as sqrt(h).
//    The top moves at a constant speed, so the time is the load.
//  - prm/brazilian_disc.prm with Table 5's Mohr-Coulomb (c = 25 MPa; the
//    first failure is in shear under a rigid plate, where the contact
//    concentrates the stress): h = 2.2 mm and 1.1 mm; the
//    load is the top plate's contact force P at the failure time
//    (interpolated within the step). R = 6.6 mm.
// R is three coarse cells in both: the average converges once R is a few
// cells (doc/fracture.md gives R = 2 h too).
// Edges are only checked, not split ('Split edges = false'): each run stops
// at the step of the first failure.
//
// Asserted: with the nonlocal average, the first failure time (and P for
// the disc) of h and h/2 within 5 %. Printed: the same for the cell
// average, which is what the nonlocal average is for.

#include <chrono>
#include <cmath>
#include <cstdlib>

#include "plates.h"
#include "tests.h"
#include "values.h"

using namespace ndda_tests;

namespace
{
  struct FirstFailure
  {
    unsigned int                n_cells = 0;
    double                      time    = 0; // s
    double                      load    = 0; // N (the disc only)
    dealii::Point<2>            location;
    ndda::fracture::FailureMode mode = ndda::fracture::FailureMode::none;
  };

  /**
   * Run @p text (a scene) with detection only and the edge stress of
   * @p radius (0: cell average) until the first edge fails; @p load gives
   * the load after a step (or 0).
   */
  template <typename Load>
  FirstFailure
  first_failure(std::string       text,
                const std::string name,
                const double      radius,
                const Load       &load)
  {
    text += "subsection Output\n  set Interval = 0\nend\n"
            "subsection Fracture\n  set Split edges = false\n";
    if (radius > 0)
      text += "  set Edge stress = nonlocal average\n"
              "  set Nonlocal radius = " +
              std::to_string(radius) + "\n";
    text += "end\n";
    const auto         parameters = read_parameters(text, name);
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    FirstFailure result;
    result.n_cells = simulator.get_mesh().get_block_mesh().triangles.size();
    double previous_load = 0;
    while (simulator.get_time() < parameters.control.end_time - 1e-12)
      {
        const double start = simulator.get_time();
        simulator.do_time_step();
        const double now     = load(simulator);
        const auto  &failure = simulator.get_first_edge_failure();
        if (failure.mode != ndda::fracture::FailureMode::none)
          {
            const double fraction =
              (failure.time - start) / (simulator.get_time() - start);
            result.time     = failure.time;
            result.load     = previous_load + fraction * (now - previous_load);
            result.location = failure.location;
            result.mode     = failure.mode;
            break;
          }
        previous_load = now;
      }
    check(result.mode != ndda::fracture::FailureMode::none,
          name + ": an edge fails before the end time");
    return result;
  }

  std::string
  with_mesh_size(const std::string &text,
                 const std::string &block,
                 const double       h)
  {
    return text + "subsection Geometry\n  subsection " + block +
           "\n    set Mesh size = " + std::to_string(h) + "\n  end\nend\n";
  }

  double
  relative_change(const double coarse, const double fine)
  {
    return std::abs(fine / coarse - 1);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);
  const auto wall_start = std::chrono::steady_clock::now();

  // A scene name, a mesh size h and a radius R (m) on the command line run
  // that scene only, with these (for doc/fracture.md's other figures).
  const std::string only  = argc > 3 ? argv[1] : "";
  const double      h_arg = argc > 3 ? std::atof(argv[2]) : 0;
  const double      R_arg = argc > 3 ? std::atof(argv[3]) : 0;

  // 1. The inclined crack.
  if (only.empty() || only == "inclined")
    {
      const double       h    = only.empty() ? 0.0025 : h_arg;
      const double       R    = only.empty() ? 0.0075 : R_arg;
      const std::string  text = read_example("inclined_crack_tension");
      const auto         none = [](const ndda::Simulator<2> &) { return 0.; };
      const std::string  key  = "nonlocal.inclined_";
      const unsigned int n_key_digits = 3;
      std::array<std::array<FirstFailure, 2>, 2> runs; // [local, nonlocal][h]
      for (unsigned int nonlocal = 0; nonlocal < 2; ++nonlocal)
        for (unsigned int k = 0; k < 2; ++k)
          {
            const double mesh = h / (1 << k);
            auto        &r    = runs[nonlocal][k];
            r = first_failure(with_mesh_size(text, "specimen", mesh),
                              "inclined_crack_tension",
                              nonlocal ? R : 0.,
                              none);
            std::cout << "inclined crack, "
                      << (nonlocal ?
                            "nonlocal R = " +
                              std::to_string(R * 1e3).substr(0, 3) + " mm" :
                            "cell average")
                      << ", h = " << mesh * 1e3 << " mm (" << r.n_cells
                      << " cells): first failure at " << r.time * 1e6 << " us ("
                      << mode_name(r.mode) << ") at (" << r.location[0] * 1e3
                      << ", " << r.location[1] * 1e3 << ") mm" << std::endl;
            record(key + (nonlocal ? "nonlocal_" : "local_") +
                     std::to_string(k) + "_time",
                   r.time * 1e6,
                   n_key_digits);
          }
      const double local_change =
        relative_change(runs[0][0].time, runs[0][1].time);
      const double nonlocal_change =
        relative_change(runs[1][0].time, runs[1][1].time);
      std::cout << "  h -> h/2 changes the first failure time by "
                << 100 * local_change << " % (cell average), "
                << 100 * nonlocal_change << " % (nonlocal)" << std::endl;
      record(key + "local_change", 100 * local_change, 2);
      record(key + "nonlocal_change", 100 * nonlocal_change, 2);
      check(nonlocal_change < 0.05,
            "inclined crack, nonlocal average: the first failure time of h "
            "and h/2 within 5 %");
    }

  // 2. The Brazilian disc with Table 5's Mohr-Coulomb.
  if (only.empty() || only == "disc")
    {
      const double      h    = only.empty() ? 0.0022 : h_arg;
      const double      R    = only.empty() ? 0.0066 : R_arg;
      const std::string text = read_example("brazilian_disc") +
                               "subsection Materials\n  subsection rock\n"
                               "    set Cohesion = 25e6\n  end\nend\n";
      const auto load = [](const ndda::Simulator<2> &simulator) {
        return plate_force(simulator, block_index(simulator, "top"));
      };
      const std::string                          key = "nonlocal.disc_";
      std::array<std::array<FirstFailure, 2>, 2> runs;
      for (unsigned int nonlocal = 0; nonlocal < 2; ++nonlocal)
        for (unsigned int k = 0; k < 2; ++k)
          {
            const double mesh = h / (1 << k);
            auto        &r    = runs[nonlocal][k];
            r = first_failure(with_mesh_size(text, "disc", mesh),
                              "brazilian_disc",
                              nonlocal ? R : 0.,
                              load);
            const double radius = 0.025;
            std::cout << "Brazilian disc (Table 5), "
                      << (nonlocal ?
                            "nonlocal R = " +
                              std::to_string(R * 1e3).substr(0, 3) + " mm" :
                            "cell average")
                      << ", h = " << mesh * 1e3 << " mm (" << r.n_cells
                      << " cells): first failure at " << r.time * 1e3 << " ms ("
                      << mode_name(r.mode) << "), P = " << r.load / 1e3
                      << " kN, at (" << r.location[0] / radius << ", "
                      << r.location[1] / radius << ") R" << std::endl;
            const std::string run =
              key + (nonlocal ? "nonlocal_" : "local_") + std::to_string(k);
            record(run + "_time", r.time * 1e3, 4);
            record(run + "_p", r.load / 1e3, 3);
            record(run + "_y", r.location[1] / radius, 2);
          }
      for (unsigned int nonlocal = 0; nonlocal < 2; ++nonlocal)
        {
          const double time_change =
            relative_change(runs[nonlocal][0].time, runs[nonlocal][1].time);
          const double load_change =
            relative_change(runs[nonlocal][0].load, runs[nonlocal][1].load);
          std::cout << "  h -> h/2 changes the first failure time by "
                    << 100 * time_change << " %, P by " << 100 * load_change
                    << " % (" << (nonlocal ? "nonlocal" : "cell average") << ")"
                    << std::endl;
          const std::string which = nonlocal ? "nonlocal_" : "local_";
          record(key + which + "time_change", 100 * time_change, 2);
          record(key + which + "p_change", 100 * load_change, 2);
          if (nonlocal)
            {
              check(time_change < 0.05,
                    "Brazilian disc, nonlocal average: the first failure time "
                    "of h and h/2 within 5 %");
              check(load_change < 0.05,
                    "Brazilian disc, nonlocal average: the first crack load "
                    "of h and h/2 within 5 %");
            }
        }
    }

  report_wall_time("nonlocal_length_scale", wall_start);
  std::cout << "OK" << std::endl;
}
