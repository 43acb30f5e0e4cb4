// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cost of a time step of the smallest contact scene (issue 15's target "a
// single rigid or affine block sliding down an incline at or below
// 0.02 ms a step"): prm/sliding_block.prm's 1 m x 0.5 m block on a
// 30 degree incline (friction 20 degrees, DDA, dt = 1 ms, penalty 50 E),
// with the incline made 50 m long so that the block slides for 7 s.
// Both blocks take `Control/Kinematics` = rigid, affine or meshed, with the
// fewest cells (Mesh size 100: the refinement at 30 degrees still cuts the
// long incline into 16 triangles, the block is 2) or with the block meshed
// as in the example (Mesh size 0.25 m). The statistics rows are recorded
// in every step (the file is written at the end), no VTU. Runs alternate
// between the models, `rounds` times; for each run: mean
// and median wall time per step over steps 11 to N, and the block's slide
// against s = g (sin 30 - cos 30 tan 20) t^2 / 2.
//
// Usage: single_block [steps] [rounds]   (default 5000, 2)

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <ndda/parameters/parameters.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  /** The scene, with model @p model and mesh sizes @p incline, @p block. */
  std::string
  scene(const std::string &model, const double incline, const double block)
  {
    std::ostringstream text;
    text << std::setprecision(17) << R"(
set Scene name = single_block
subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = 1e-3
  set End time        = 7
  set Maximum displacement ratio = 0.01
  set Kinematics = )"
         << model << R"(
end
subsection Contact
  set Penalty factor = 50
end
subsection Materials
  set Names = rock
  subsection rock
    set Density         = 2600
    set Young's modulus = 1e9
    set Poisson's ratio = 0.25
  end
  subsection Joint
    set Friction angle = 20
  end
end
subsection Geometry
  set Blocks = incline, block
  subsection incline
    set Outer boundary = -43.301270189221936, -25; 4.3301270189221936, -25; 4.3301270189221936, 2.4999999999999996
    set Material  = rock
    set Mesh size = )"
         << incline << R"(
  end
  subsection block
    set Outer boundary = 3.0310889132455356, 1.7499999999999998; 3.897114317029974, 2.2499999999999996; 3.647114317029974, 2.6830127018922187; 2.7810889132455356, 2.1830127018922192
    set Material  = rock
    set Mesh size = )"
         << block << R"(
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = ground
  subsection ground
    set Type     = fixed
    set Segments = -43.301270189221936, -25, 4.3301270189221936, -25; 4.3301270189221936, -25, 4.3301270189221936, 2.4999999999999996
  end
end
subsection Output
  set Write vtu = false
  set Measure points = 3.3391016151377548, 2.2165063509461094
end
)";
    return text.str();
  }

  void
  run(const std::string &model,
      const double       incline,
      const double       block,
      const unsigned int steps)
  {
    dealii::ParameterHandler     prm;
    ndda::parameters::Parameters parameters;
    parameters.read(scene(model, incline, block), "single_block.prm", prm);
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    const unsigned int  skip = 10;
    std::vector<double> times;
    for (unsigned int s = 0; s < steps + skip; ++s)
      {
        const auto start = std::chrono::steady_clock::now();
        simulator.do_time_step();
        if (s >= skip)
          times.push_back(std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start)
                            .count());
      }
    double total = 0;
    for (const double t : times)
      total += t;
    std::vector<double> sorted(times);
    std::sort(sorted.begin(), sorted.end());
    const auto  &u = simulator.get_measure_histories()[0].back();
    const double t = simulator.get_time();
    const double exact =
      0.5 * 9.81 * (0.5 - std::cos(M_PI / 6) * std::tan(M_PI / 9)) * t * t;
    const double slide = u.displacement.norm();
    std::cout
      << std::setw(8) << model << std::setw(8)
      << simulator.get_dof_handler().get_triangulation().n_active_cells()
      << std::setw(7) << simulator.get_dof_handler().n_dofs() << std::fixed
      << std::setprecision(4) << std::setw(10) << 1e3 * total / times.size()
      << std::setw(10) << 1e3 * sorted[sorted.size() / 2]
      << std::setprecision(2) << std::setw(10) << 100 * (slide / exact - 1)
      << std::defaultfloat << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int steps  = argc > 1 ? std::atoi(argv[1]) : 5000;
  const unsigned int rounds = argc > 2 ? std::atoi(argv[2]) : 2;
  std::cout << "steps 11 to " << steps + 10 << " of each run" << std::endl;
  std::cout << std::setw(8) << "model" << std::setw(8) << "cells"
            << std::setw(7) << "DoFs" << std::setw(10) << "ms/step"
            << std::setw(10) << "median" << std::setw(10) << "slide %"
            << std::endl;
  for (unsigned int r = 0; r < rounds; ++r)
    for (const auto &[incline, block] :
         std::vector<std::pair<double, double>>{{100., 100.}, {100., 0.25}})
      for (const std::string model : {"rigid", "affine", "meshed"})
        run(model, incline, block, steps);
}
