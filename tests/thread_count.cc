// SPDX-License-Identifier: GPL-3.0-or-later
//
// A run's results do not depend on the number of threads beyond one:
// ndda's loops over cells run on deal.II's threads, write per-cell results
// and sum them in cell order on one thread, and deal.II's own vector
// reductions stay on one thread (ndda::set_up_threads()). On one thread
// deal.II's FEValues reuses the mapping data of a cell for the next cell
// when it is a translation of it, and on more threads never does
// (FEValuesBase::check_cell_similarity() in deal.II 9.4): element matrices
// then differ in their last bits, so a run on one thread agrees with one
// on two to round-off only. A beam of about 10,000 cells (several tasks of
// StressField's loops) swings under gravity and a pulse, clamped at its
// left end, with a small matrix update tolerance so that steps rebuild
// some cells' matrices; it is run on 1, 2 and 3 threads. On 2 and 3 the
// displacement, velocity and every stress must agree to the last bit; on
// 1 and 2 to 1e-9 of the largest value of each kind.

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
    /// The number of displacement and velocity values (before the
    /// stresses).
    std::size_t n_kinematic = 0;
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
    result.n_kinematic = result.values.size();
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
  const Result two = run(2);
  check(MultithreadInfo::n_threads() == 2, "the thread limit was not set");
  const Result three = run(3);
  check(MultithreadInfo::n_threads() == 3, "the thread limit was not set");
  check(two.values.size() == one.values.size() &&
          three.values.size() == one.values.size(),
        "the runs differ in size");

  unsigned int differing = 0;
  for (std::size_t i = 0; i < two.values.size(); ++i)
    if (three.values[i] != two.values[i])
      ++differing;
  std::cout << "3 threads against 2: values that differ " << differing
            << " of more than 1e4" << std::endl;
  check(differing == 0, "the results depend on the number of threads");

  // Displacements, velocities and stresses, each against its largest
  // value.
  const std::size_t n_stress = one.values.size() - one.n_kinematic;
  double            worst    = 0;
  for (const auto &[begin, end] :
       {std::pair<std::size_t, std::size_t>(0, one.n_kinematic / 2),
        std::pair<std::size_t, std::size_t>(one.n_kinematic / 2,
                                            one.n_kinematic),
        std::pair<std::size_t, std::size_t>(one.n_kinematic,
                                            one.n_kinematic + n_stress)})
    {
      double scale = 0, difference = 0;
      for (std::size_t i = begin; i < end; ++i)
        {
          scale = std::max(scale, std::abs(one.values[i]));
          difference =
            std::max(difference, std::abs(two.values[i] - one.values[i]));
        }
      worst = std::max(worst, scale > 0 ? difference / scale : difference);
    }
  std::cout << "2 threads against 1: largest difference relative to the "
               "largest value of its kind "
            << (worst <= 1e-9 ? "at most 1e-9" : "more than 1e-9") << std::endl;
  check(worst <= 1e-9, "one thread and two differ beyond round-off");
  std::cout << "OK" << std::endl;
}
