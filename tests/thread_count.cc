// SPDX-License-Identifier: GPL-3.0-or-later
//
// A run's results do not depend on the number of threads: ndda's loops
// over cells run on deal.II's threads, write per-cell results and sum them
// in cell order on one thread, and deal.II's own vector reductions stay on
// one thread (ndda::set_up_threads()).
//
// First, the mapping. On one thread deal.II 9.4's FEValues reuses the
// mapping data of a cell for the next cell when it is a translation of it,
// and on more threads never does (FEValuesBase::check_cell_similarity());
// the two differ in their last bits. ndda::LinearMapping computes every
// cell afresh: on a grid of translated cells, one FEValues moved from cell
// to cell must give the same gradients and weights, bit for bit, as a new
// FEValues on each cell; deal.II's MappingFE must not (or the check shows
// nothing).
//
// Then a run. A beam of about 10,000 cells (several tasks of StressField's
// loops) swings under gravity and a pulse, clamped at its left end, with a
// small matrix update tolerance so that steps rebuild some cells'
// matrices; it is run on 1, 2 and 3 threads. The displacement, velocity
// and every stress must agree to the last bit.
//
// Last, contacts. The passes over all contacts (the narrow phase of the
// detection, the states after each solve, the largest depths) run on the
// threads too, each contact into its own slot. A staggered wall of 1,000
// rigid bricks (more than 3,000 contacts: several tasks each) drops under
// gravity switched on at once, on 1, 2 and 3 threads; the displacement,
// velocity and the contact counts of every step (candidates, contacts,
// closed, sliding, open-close iterations) must agree to the last bit.

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>

#include <ndda/physics/finite_element.h>

#include <array>
#include <iomanip>
#include <map>
#include <sstream>

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
  /** The wall of the last part: @p courses courses of @p length bricks of
   * 1 m x 0.5 m, half bricks at the ends of every second course, on a
   * fixed base. */
  std::string
  wall(const unsigned int courses, const unsigned int length)
  {
    std::ostringstream joints;
    joints << std::setprecision(10);
    std::string separator;
    for (unsigned int c = 1; c < courses; ++c)
      {
        joints << separator << "0, " << 0.5 * c << ", " << length << ", "
               << 0.5 * c;
        separator = "; ";
      }
    for (unsigned int c = 0; c < courses; ++c)
      for (unsigned int i = 1; i <= length; ++i)
        {
          const double x = i - (c % 2 == 1 ? 0.5 : 0.);
          if (x > 0 && x < length)
            joints << separator << x << ", " << 0.5 * c << ", " << x << ", "
                   << 0.5 * (c + 1);
        }
    const double       h = 0.5 * courses;
    std::ostringstream text;
    text << std::setprecision(10) << R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = 2e-3
  set End time        = 1
  set Kinematics      = rigid
end
subsection Contact
  set Penalty factor = 10
end
subsection Materials
  set Names = rock
  subsection rock
    set Density         = 2600
    set Young's modulus = 10e9
    set Poisson's ratio = 0.25
  end
  subsection Joint
    set Friction angle = 35
  end
end
subsection Geometry
  set Blocks  = base
  set Regions = wall
  subsection base
    set Outer boundary = -1, -1; )"
         << length + 1 << ", -1; " << length + 1 << R"(, 0; -1, 0
    set Material = rock
    set Mesh size = 2
  end
  subsection wall
    set Outer boundary = 0, 0; )"
         << length << ", 0; " << length << ", " << h << "; 0, " << h << R"(
    set Joints = )"
         << joints.str() << R"(
    set Material = rock
    set Mesh size = 2
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = ground
  subsection ground
    set Type     = fixed
    set Segments = -1, -1, )"
         << length + 1 << R"(, -1
  end
end
)";
    return text.str();
  }



  /**
   * The number of values (shape gradients and JxW) in which one FEValues
   * on @p mapping, moved from a cell of a grid of triangles to one that is
   * a translation of it, differs on the second from a new FEValues on it;
   * on one thread. The grid's coordinates are not binary fractions, so the
   * Jacobians of translated cells differ in their last bits.
   */
  unsigned int
  values_changed_by_reuse(const dealii::Mapping<2> &mapping)
  {
    using namespace dealii;
    MultithreadInfo::set_thread_limit(1);
    Triangulation<2> triangulation;
    GridGenerator::subdivided_hyper_rectangle_with_simplices(
      triangulation, {30, 20}, Point<2>(0.1, 0.3), Point<2>(1.3, 1.1));
    const FE_SimplexP<2>   fe(2);
    const QGaussSimplex<2> quadrature(3);
    const UpdateFlags      flags  = update_gradients | update_JxW_values;
    const auto             values = [&](const FEValues<2> &v) {
      std::vector<double> out;
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          out.push_back(v.JxW(q));
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            for (unsigned int d = 0; d < 2; ++d)
              out.push_back(v.shape_grad(i, q)[d]);
        }
      return out;
    };
    // The last cell of each shape (edge vectors to 1e-9).
    std::map<std::array<long long, 4>, Triangulation<2>::cell_iterator> last;
    unsigned int differing = 0, pairs = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const Tensor<1, 2> a = cell->vertex(1) - cell->vertex(0),
                           b = cell->vertex(2) - cell->vertex(0);
        const std::array<long long, 4> shape   = {{std::llround(a[0] * 1e9),
                                                   std::llround(a[1] * 1e9),
                                                   std::llround(b[0] * 1e9),
                                                   std::llround(b[1] * 1e9)}};
        const auto                     earlier = last.find(shape);
        if (earlier != last.end() && cell->is_translation_of(earlier->second))
          {
            FEValues<2> moved(mapping, fe, quadrature, flags);
            moved.reinit(earlier->second);
            moved.reinit(cell);
            FEValues<2> fresh(mapping, fe, quadrature, flags);
            fresh.reinit(cell);
            const auto x = values(moved);
            const auto y = values(fresh);
            for (std::size_t k = 0; k < x.size(); ++k)
              if (x[k] != y[k])
                ++differing;
            ++pairs;
          }
        last[shape] = cell;
      }
    check(pairs > 100, "too few translated cells");
    return differing;
  }



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

  /** The wall on @p n_threads threads, 10 steps: displacement and velocity,
   * and per step the contact counts. */
  std::pair<std::vector<double>, std::vector<unsigned int>>
  run_wall(const unsigned int n_threads)
  {
    dealii::MultithreadInfo::set_thread_limit(n_threads);
    auto               parameters = read_parameters(wall(25, 40), "wall");
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    std::vector<unsigned int> counts;
    for (unsigned int step = 0; step < 10; ++step)
      {
        simulator.do_time_step();
        const auto &s = simulator.get_contacts().get_statistics();
        counts.insert(counts.end(),
                      {s.n_candidates,
                       s.n_contacts,
                       s.n_closed,
                       s.n_sliding,
                       s.n_iterations});
      }
    const auto         &d = simulator.get_displacement();
    const auto         &v = simulator.get_velocity();
    std::vector<double> values(d.begin(), d.end());
    values.insert(values.end(), v.begin(), v.end());
    return {values, counts};
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const unsigned int by_deal_ii =
    values_changed_by_reuse(MappingFE<2>(FE_SimplexP<2>(1)));
  const unsigned int by_ndda = values_changed_by_reuse(ndda::linear_mapping());
  std::cout << "one FEValues moved over translated cells against a new one "
               "on each: MappingFE values that differ "
            << (by_deal_ii > 0 ? "some" : "none")
            << ", ndda::LinearMapping values that differ " << by_ndda
            << std::endl;
  check(by_deal_ii > 0,
        "deal.II's MappingFE no longer reuses a translated cell's data: the "
        "check below shows nothing");
  check(by_ndda == 0, "ndda::LinearMapping reuses a translated cell's data");

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

  for (const auto &[name, other] :
       {std::pair<std::string, const Result *>("2 threads against 1", &two),
        std::pair<std::string, const Result *>("3 threads against 1", &three)})
    {
      unsigned int differing = 0;
      for (std::size_t i = 0; i < one.values.size(); ++i)
        if (other->values[i] != one.values[i])
          ++differing;
      std::cout << name << ": values that differ " << differing
                << " of more than 1e4" << std::endl;
      check(differing == 0, "the results depend on the number of threads");
    }

  const auto wall_one = run_wall(1);
  check(wall_one.second[1] > 3000, "too few contacts for several tasks");
  check(wall_one.second[2] > 0, "no contact closed");
  std::cout << "wall, 1 thread: more than 3000 contacts, some closed"
            << std::endl;
  for (const unsigned int n : {2u, 3u})
    {
      const auto   wall_n    = run_wall(n);
      unsigned int differing = 0;
      for (std::size_t i = 0; i < wall_one.first.size(); ++i)
        if (wall_n.first[i] != wall_one.first[i])
          ++differing;
      std::cout << "wall, " << n << " threads against 1: values that differ "
                << differing << ", contact counts "
                << (wall_n.second == wall_one.second ? "the same" : "different")
                << std::endl;
      check(differing == 0 && wall_n.second == wall_one.second,
            "the contacts depend on the number of threads");
    }
  std::cout << "OK" << std::endl;
}
