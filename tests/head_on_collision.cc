// SPDX-License-Identifier: GPL-3.0-or-later
//
// Two equal 0.5 m x 0.5 m blocks collide head on, frictionless, without
// gravity (issue 16): the striker comes at 1 m/s, the struck block is at
// rest. Momentum and energy kept, the striker stops and the struck block
// leaves at 1 m/s; the elastic waves of a soft penalty contact (the
// contact lasts far longer than a wave takes to cross a block) leave
// almost nothing behind. Targets: the striker keeps under 2 % of its
// speed, the struck block leaves with 98-100 %, momentum kept to 1e-9.
//
// The block drop's settings (E 50 GPa, penalty 0.01 E, dt = 0.1 ms) as a
// new user would take them, generalized-alpha at rho_inf = 0, blocks meshed
// at 0.1 m: the sixteen springs of the contact face give the contact a
// frequency omega dt = 0.5, which generalized-alpha damps: the striker
// keeps 3.3 % (not met; printed and recorded, not asserted). With
// dt = 20 us (omega dt = 0.1) the targets are met and asserted. At
// rho_inf = 0.5 and 0.1 ms the energy and momentum are kept (asserted: a
// system matrix kept from generalized-alpha's first step once gained
// 2e4 J here) and the striker's remainder is printed. Each
// block's velocity is its momentum over its mass (x components of M v
// over the block's dofs).

#include <cmath>

#include "tests.h"

using namespace ndda_tests;

namespace
{
  const std::string scene = R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = generalized-alpha
  set Time step       = {dt}
  set End time        = 0.03
  set Maximum displacement ratio = 0.01
  set Matrix update tolerance    = 0.05
  subsection generalized-alpha
    set Spectral radius at infinity = {rho}
  end
end
subsection Contact
  set Penalty factor = 0.01
  set Maximum penetration ratio = 5e-3
end
subsection Materials
  set Names = rock
  subsection rock
    set Density = 2600
    set Young's modulus = 50e9
    set Poisson's ratio = 0.25
  end
  subsection Joint
    set Friction angle = 0
  end
end
subsection Geometry
  set Blocks = striker, struck
  subsection striker
    set Outer boundary = -0.51, 0; -0.01, 0; -0.01, 0.5; -0.51, 0.5
    set Material = rock
    set Mesh size = 0.1
    set Initial velocity = 1; 0
  end
  subsection struck
    set Outer boundary = 0, 0; 0.5, 0; 0.5, 0.5; 0, 0.5
    set Material = rock
    set Mesh size = 0.1
  end
end
)";

  struct Result
  {
    double       striker, struck; // velocities over the initial one
    double       momentum_error;  // relative
    double       largest_gain;    // J
    unsigned int cuts;
  };

  Result
  run(const std::string &dt, const std::string &rho)
  {
    using namespace dealii;
    ndda::Simulator<2> simulator(
      read_parameters(substitute(scene, {{"dt", dt}, {"rho", rho}}),
                      "head_on_collision"));
    simulator.setup();
    // x-component indicators of the two blocks' dofs.
    const auto    &dof_handler = simulator.get_dof_handler();
    const auto    &fe          = dof_handler.get_fe();
    Vector<double> ex[2];
    for (auto &e : ex)
      e.reinit(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        const unsigned int block =
          simulator.get_mesh().block_of_cell(cell->active_cell_index());
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (fe.system_to_component_index(i).first == 0)
            ex[block][dofs[i]] = 1;
      }
    const auto momenta = [&]() {
      Vector<double> mv(dof_handler.n_dofs());
      simulator.get_mass_matrix().vmult(mv, simulator.get_velocity());
      return std::array<double, 2>{{mv * ex[0], mv * ex[1]}};
    };
    // The mass matrix is assembled in the first step: the momentum at the
    // start is the striker's mass times 1 m/s (the consistent mass matrix
    // sums to the mass).
    const double mass = 2600. * 0.5 * 0.5;
    const double p0   = mass * 1.;
    Result       result{};
    while (simulator.get_time() < 0.03 - 1e-12)
      {
        simulator.do_time_step();
        result.cuts += simulator.get_step_report().cuts;
        result.largest_gain =
          std::max(result.largest_gain, simulator.energy_error());
      }
    const auto p          = momenta();
    result.striker        = p[0] / mass;
    result.struck         = p[1] / mass;
    result.momentum_error = std::abs(p[0] + p[1] - p0) / std::abs(p0);
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto wall_start = std::chrono::steady_clock::now();
  std::cout << std::setprecision(4);
  for (const std::string dt : {"1e-4", "2e-5"})
    {
      const Result r = run(dt, "0");
      const bool   hit =
        std::abs(r.striker) < 0.02 && r.struck >= 0.98 && r.struck <= 1. + 1e-9;
      std::cout << "dt " << dt << ": striker keeps " << 100 * r.striker
                << " %, struck block leaves with " << 100 * r.struck
                << " %, momentum error " << r.momentum_error << ", " << r.cuts
                << " step cuts; targets " << (hit ? "met" : "NOT met")
                << std::endl;
      const std::string key = "head_on_collision.dt_" + dt + ".";
      record(key + "striker", 100 * r.striker, 2);
      record(key + "struck", 100 * r.struck, 4);
      record(key + "momentum_error", r.momentum_error, 2);
      record(key + "met", met(hit && r.momentum_error < 1e-9));
      check(r.momentum_error < 1e-9, "momentum kept to 1e-9");
      if (dt == "2e-5")
        check(hit, "dt 2e-5: striker under 2 %, struck 98-100 %");
    }
  // rho_inf = 0.5, whose first step has a mass coefficient of its own (the
  // system matrix must be assembled again for the second): energy and
  // momentum kept, the striker's remainder printed.
  {
    const Result r = run("1e-4", "0.5");
    std::cout << "dt 1e-4, rho_inf = 0.5: striker keeps " << 100 * r.striker
              << " %, struck block leaves with " << 100 * r.struck
              << " %, momentum error " << r.momentum_error
              << ", largest energy gain " << r.largest_gain << " J of "
              << 0.5 * 2600. * 0.5 * 0.5 << " J" << std::endl;
    record("head_on_collision.rho_0.5.striker", 100 * r.striker, 2);
    record("head_on_collision.rho_0.5.struck", 100 * r.struck, 4);
    record("head_on_collision.rho_0.5.momentum_error", r.momentum_error, 2);
    record("head_on_collision.rho_0.5.largest_gain", r.largest_gain, 2);
    check(r.momentum_error < 1e-9 && r.largest_gain < 1e-6,
          "rho_inf = 0.5: momentum and energy kept");
  }
  report_wall_time("head_on_collision", wall_start);
  std::cout << "OK" << std::endl;
}
