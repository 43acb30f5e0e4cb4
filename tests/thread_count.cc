// SPDX-License-Identifier: GPL-3.0-or-later
//
// A run's results do not depend on the number of threads: ndda's loops
// over cells run on deal.II's threads, write per-cell results and sum
// them in cell order on one thread, and deal.II's own vector and matrix
// operations stay on one thread (ndda::set_up_threads()). A beam of about
// 10,000 cells (several tasks of StressField's loops) swings under
// gravity and a pulse, clamped at its left end, with a small matrix update
// tolerance so that steps rebuild some cells' matrices; it is run on 1, 2
// and 3 threads, and the displacement, velocity and every stress must
// agree to the last bit.

#include <deal.II/base/multithread_info.h>

#include "tests.h"

using namespace ndda_tests;

const std::string scene = R"(
subsection Control
  set Analysis type = dynamic
  set Time step = 1e-3
  set End time = 1
  set Matrix update tolerance = 1e-4
end
subsection Materials
  set Names = rock
  set Plane condition = plane stress
  subsection rock
    set Young's modulus = 1e8
    set Poisson's ratio = 0.25
    set Density = 2000
  end
end
subsection Geometry
  set Blocks = beam
  subsection beam
    set Outer boundary = 0, 0; 4, 0; 4, 0.5; 0, 0.5
    set Material = rock
    set Mesh size = 0.03
  end
end
subsection Loads
  set Gravity = 0; -9.81
  set Line loads = pulse
  subsection pulse
    set Segment = 4, 0, 4, 0.5
    set Type = traction
    set Value = 0; 2e5 * (t < 0.01)
  end
end
subsection Boundary conditions
  set Names = clamp
  subsection clamp
    set Type = fixed
    set Segments = 0, 0, 0, 0.5
  end
end
)";

namespace
{
  struct Result
  {
    std::vector<double> values;
    unsigned int        cells    = 0;
    unsigned int        rebuilds = 0;
  };

  Result
  run(const unsigned int n_threads)
  {
    dealii::MultithreadInfo::set_thread_limit(n_threads);
    auto               parameters = read_parameters(scene, "beam");
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    Result result;
    for (unsigned int step = 0; step < 30; ++step)
      {
        simulator.do_time_step();
        const unsigned int rebuilt = simulator.get_discretization()
                                       .element_cache.get_computed_cells()
                                       .size();
        if (step > 0 && rebuilt > 0)
          ++result.rebuilds;
      }
    result.cells  = simulator.get_mesh().get_triangulation().n_active_cells();
    const auto &d = simulator.get_displacement();
    const auto &v = simulator.get_velocity();
    result.values.assign(d.begin(), d.end());
    result.values.insert(result.values.end(), v.begin(), v.end());
    for (const auto &sigma : simulator.get_stresses().values())
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          result.values.push_back(sigma[i][j]);
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const Result one = run(1);
  check(one.cells > 8000, "too few cells for several tasks");
  check(one.rebuilds > 0, "no step rebuilt a cell's matrices");
  check(one.values.size() > 10000, "too few values to compare");
  std::cout << "1 thread: more than 8000 cells, steps that rebuilt cells "
            << (one.rebuilds > 0 ? "some" : "none") << std::endl;
  for (const unsigned int n : {2u, 3u})
    {
      const Result other     = run(n);
      unsigned int differing = 0;
      for (std::size_t i = 0; i < one.values.size(); ++i)
        if (other.values[i] != one.values[i])
          ++differing;
      std::cout << n << " threads (deal.II has " << MultithreadInfo::n_threads()
                << "): values that differ from 1 thread's " << differing
                << " of "
                << (one.values.size() > 10000 ? "more than 1e4" : "fewer")
                << std::endl;
      check(MultithreadInfo::n_threads() == n, "the thread limit was not set");
      check(other.values.size() == one.values.size() && differing == 0,
            "the results depend on the number of threads");
    }
  std::cout << "OK" << std::endl;
}
