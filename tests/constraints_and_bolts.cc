// SPDX-License-Identifier: GPL-3.0-or-later
//
// Constraint, bolt and viscosity kernels, and the linear solver back ends:
//
// 1. A block on rollers inclined at 30 degrees under gravity slides along
//    the rollers with u = -g sin(30) t^2 / 2 along them and no motion
//    normal to them, with exact constraints and with the thesis's penalty
//    springs; and the same with UMFPACK, KLU and CG-AMG.
// 2. A bolt between two blocks: one block is clamped, a force F pulls the
//    other, which slides on rollers; the bolt stretches by F / k. With
//    pretension P and no force the gap closes by P / k.
// 3. Viscosity: a sliding block with viscosity mu and density rho slows
//    down as v0 exp(-mu t / rho); the viscous dissipation is the kinetic
//    energy it loses, and the energy balance closes to round-off.

#include <cmath>

#include "tests.h"

using namespace ndda_tests;

const std::string roller_scene = R"(
subsection Control
  set Time step = 1e-3
  set End time = 0.1
  set Constraint method = {method}
  set Penalty factor = 1e4
  set Linear solver = {solver}
  set Solver tolerance = 1e-12
end
subsection Materials
  set Names = rock
  subsection rock
    set Density = 2000
    set Young's modulus = 1e12
  end
end
subsection Geometry
  set Blocks = block
  subsection block
    set Outer boundary = 0, 0; 1, 0; 1, 1; 0, 1
    set Material = rock
    set Mesh size = 0.2
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = rollers
  subsection rollers
    set Type = roller
    set Roller angle = 30
    set Segments = 0, 0, 1, 0
  end
end
subsection Output
  set Measure points = 0.5, 0.5
end
)";

const std::string bolt_scene = R"(
subsection Control
  set Analysis type = static
  set Time step = 10
  set End time = 30
  set Maximum displacement ratio = 0.5
end
subsection Materials
  set Names = steel
  subsection steel
    set Density = 1000
    set Young's modulus = 1e13
  end
end
subsection Geometry
  set Blocks = left, right
  subsection left
    set Outer boundary = 0, 0; 1, 0; 1, 1; 0, 1
    set Material = steel
    set Mesh size = 0.25
  end
  subsection right
    set Outer boundary = 1.1, 0; 2.1, 0; 2.1, 1; 1.1, 1
    set Material = steel
    set Mesh size = 0.25
  end
end
subsection Loads
  set Point loads = pull
  subsection pull
    set Point = 1.6, 0.5
    set Force = {force}; 0
  end
end
subsection Boundary conditions
  # The right block slides on rollers, so that only the bolt holds it in x.
  set Names = clamp, guide
  subsection clamp
    set Type = fixed
    set Segments = 0, 0, 0, 1
  end
  subsection guide
    set Type = roller
    set Roller angle = 0
    set Segments = 1.1, 0, 2.1, 0
  end
end
subsection Bolts
  set Names = bolt
  subsection bolt
    set End points = 0.9, 0.5, 1.2, 0.5
    set Stiffness = 1e7
    set Pretension = {pretension}
  end
end
subsection Output
  set Measure points = 0.9, 0.5; 1.2, 0.5
end
)";

const std::string viscous_scene = R"(
subsection Control
  set Time integrator = Newmark
  set Time step = 1e-3
  set End time = 1
  set Maximum displacement ratio = 0.5
end
subsection Materials
  set Names = mud
  subsection mud
    set Density = 2000
    set Young's modulus = 1e8
    set Viscosity = 2000
  end
end
subsection Geometry
  set Blocks = block
  subsection block
    set Outer boundary = 0, 0; 1, 0; 1, 1; 0, 1
    set Material = mud
    set Mesh size = 0.25
    set Initial velocity = 1; 0
  end
end
subsection Output
  set Measure points = 0.5, 0.5
end
)";

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // 1. Rollers.
  const double a = M_PI / 6, t = 0.1, g = 9.81;
  const double along = -0.5 * g * std::sin(a) * t * t;
  for (const auto &[method, solver] :
       std::vector<std::pair<std::string, std::string>>{{"exact", "UMFPACK"},
                                                        {"exact", "KLU"},
                                                        {"exact", "CG-AMG"},
                                                        {"penalty", "UMFPACK"}})
    {
      auto parameters =
        read_parameters(substitute(roller_scene,
                                   {{"method", method}, {"solver", solver}}),
                        "rollers");
      ndda::Simulator<2> simulator(parameters);
      simulator.setup();
      while (simulator.get_time() < t - 1e-12)
        simulator.do_time_step();
      const auto  &u = simulator.get_measure_histories()[0].back().displacement;
      Tensor<1, 2> tangent, normal;
      tangent[0] = std::cos(a);
      tangent[1] = std::sin(a);
      normal[0]  = -std::sin(a);
      normal[1]  = std::cos(a);
      // The block also deforms elastically under its weight (and vibrates,
      // the load being sudden), of order rho g h^2 / E = 2e-8 m: a
      // relative 1e-6 of the sliding distance.
      const double along_error =
        std::abs(u * tangent - along) / std::abs(along);
      std::cout << "rollers, " << method << " constraints, " << solver
                << ": displacement along the rollers " << u * tangent
                << " m (exact " << along << "), relative error "
                << std::scientific << std::setprecision(2) << along_error
                << ", normal " << u * normal << " m" << std::defaultfloat
                << std::setprecision(6) << std::endl;
      const std::string key =
        "constraints_and_bolts." + method + "_" + solver + ".";
      record(key + "along_error", along_error, 2);
      record(key + "normal", std::abs(u * normal), 2);
      check(along_error < (method == "exact" ? 1e-6 : 1e-3), "roller sliding");
      check(std::abs(u * normal) < 1e-7, "motion normal to the rollers");
    }

  // 2. Bolts.
  for (const auto &[force, pretension] :
       std::vector<std::pair<double, double>>{{1e4, 0}, {0, 5e3}})
    {
      auto parameters = read_parameters(
        substitute(bolt_scene,
                   {{"force", std::to_string(force)},
                    {"pretension", std::to_string(pretension)}}),
        "bolt");
      ndda::Simulator<2> simulator(parameters);
      simulator.run();
      const auto  &h = simulator.get_measure_histories();
      const double stretch =
        h[1].back().displacement[0] - h[0].back().displacement[0];
      const double exact = (force - pretension) / 1e7;
      const double error = std::abs(stretch - exact) / std::abs(exact);
      std::cout << "bolt, force " << force << " N, pretension " << pretension
                << " N: stretch " << stretch << " m (exact " << exact
                << "), relative error " << std::scientific
                << std::setprecision(2) << error << std::defaultfloat
                << std::setprecision(6) << std::endl;
      record(std::string("constraints_and_bolts.bolt_") +
               (pretension > 0 ? "pretension" : "pull") + ".error",
             error,
             2);
      check(error < 1e-4, "bolt stretch");
    }

  // 3. Viscosity: mu / rho = 1 / s.
  {
    auto               parameters = read_parameters(viscous_scene, "viscous");
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    while (simulator.get_time() < 1 - 1e-12)
      simulator.do_time_step();
    const double v = simulator.get_measure_histories()[0].back().velocity[0];
    const double exact = std::exp(-1.);
    const double error = std::abs(v - exact) / exact;
    std::cout << "viscosity: velocity after 1 s " << v << " m/s (exact "
              << exact << "), relative error " << std::scientific
              << std::setprecision(2) << error << std::endl;
    record("constraints_and_bolts.viscous_error", error, 2);
    check(error < 1e-3, "viscous decay");
    // The energy balance closes: with Newmark (the scene's) and C a
    // multiple of M, the kinetic energy lost in a step is d^T C d / dt
    // exactly, so the numerical energy is round-off.
    const double initial = 0.5 * 2000. * 1. * 1.; // 1/2 m v0^2 (J)
    const double numerical =
      simulator.numerical_energy(simulator.kinetic_energy(),
                                 simulator.strain_energy());
    std::cout << "viscosity: viscous dissipation "
              << simulator.viscous_dissipation() << " J, numerical energy "
              << numerical << " J (kinetic " << simulator.kinetic_energy()
              << " J, strain " << simulator.strain_energy() << " J, gain "
              << simulator.energy_error() << " J)" << std::endl;
    check(std::abs(numerical) < 1e-9 * initial,
          "viscous dissipation closes the energy balance");
    check(std::abs(simulator.viscous_dissipation() / initial -
                   (1. - std::exp(-2.))) < 1e-3,
          "viscous dissipation is the kinetic energy lost");
  }
  std::cout << "OK" << std::endl;
}
