// SPDX-License-Identifier: GPL-3.0-or-later
//
// Linear solver = CG-Jacobi against the direct solver, on the two kinds of
// system it meets:
//
// 1. The elastic bar of prm/elastic_bar_wave.prm, its mesh halved (about
//    18,000 dofs, so that the matrix-vector products run on several
//    threads), with the pulse travelling into it (Newmark, dt = 1e-6 s, a
//    symmetric positive definite K + c M): CG. Displacement and velocity
//    after 30 steps agree with the direct solver's to 1e-9 relative (the
//    solver tolerance is 1e-12); the run on one thread and on two gives
//    the same bits (deal.II's matrix-vector products on the threads sum
//    each row in its order, ndda keeps the vector reductions on one
//    thread).
// 2. The sliding block of prm/sliding_block.prm (30 degree incline, 20
//    degree friction, penalty springs 100 E): sliding friction makes the
//    matrix non-symmetric, so BiCGStab. The same contacts slide in every
//    step, and the block's displacement and velocity agree with the direct
//    solver's to 1e-9 relative.
// 3. The solver alone on a small matrix that is neither symmetric nor has
//    a positive diagonal (contact springs with friction can make a
//    diagonal entry negative, as in the default scene): BiCGStab reaches
//    the tolerance, and CG solves the symmetric positive definite part.

#include <deal.II/base/multithread_info.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ndda/physics/cg_jacobi.h>

#include "tests.h"

using namespace ndda_tests;


namespace
{
  /** The largest difference of @p a and @p b over the largest |b|. */
  double
  relative_difference(const std::vector<double> &a,
                      const std::vector<double> &b)
  {
    double difference = 0, scale = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      {
        difference = std::max(difference, std::abs(a[i] - b[i]));
        scale      = std::max(scale, std::abs(b[i]));
      }
    return difference / scale;
  }

  struct Run
  {
    std::vector<double>       values;
    std::vector<unsigned int> sliding;
    unsigned int              iterations = 0;
  };

  /** @p steps steps of @p scene with @p solver on @p n_threads threads:
   * the displacement and velocity, and the sliding contacts of every
   * step. */
  Run
  run(const std::string &scene,
      const std::string &name,
      const std::string &solver,
      const unsigned int steps,
      const unsigned int n_threads)
  {
    dealii::MultithreadInfo::set_thread_limit(n_threads);
    ndda::Simulator<2> simulator(
      read_parameters(substitute(scene, {{"solver", solver}}), name));
    simulator.setup();
    Run result;
    for (unsigned int step = 0; step < steps; ++step)
      {
        simulator.do_time_step();
        result.sliding.push_back(
          simulator.get_contacts().get_statistics().n_sliding);
      }
    const auto &d = simulator.get_displacement();
    const auto &v = simulator.get_velocity();
    result.values.assign(d.begin(), d.end());
    result.values.insert(result.values.end(), v.begin(), v.end());
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // The solver and its tolerance, and no VTU files, for an example scene.
  const std::string solver_entries =
    "subsection Control\n  set Linear solver = {solver}\n"
    "  set Solver tolerance = 1e-12\nend\n"
    "subsection Output\n  set Write vtu = false\nend\n";

  // 1. The bar.
  const std::string bar_scene =
    set_entry(read_example("elastic_bar_wave"), "Mesh size", "0.003") +
    solver_entries;
  const Run    direct         = run(bar_scene, "bar", "direct", 30, 2);
  const Run    cg             = run(bar_scene, "bar", "CG-Jacobi", 30, 2);
  const Run    cg_one         = run(bar_scene, "bar", "CG-Jacobi", 30, 1);
  const double bar_difference = relative_difference(cg.values, direct.values);
  std::cout << "elastic bar, 30 Newmark steps, " << direct.values.size() / 2
            << " dofs: CG-Jacobi against direct, relative difference "
            << std::scientific << std::setprecision(1) << bar_difference
            << std::defaultfloat << " (at most 1e-9)"
            << "; one thread against two: "
            << (cg_one.values == cg.values ? "the same bits" : "DIFFERENT")
            << std::endl;
  check(bar_difference < 1e-9, "CG-Jacobi against direct on the bar");
  check(cg_one.values == cg.values, "CG-Jacobi on one thread and on two");

  // 2. The sliding block.
  const std::string block_scene =
    read_example("sliding_block") + solver_entries;
  const Run    block_direct  = run(block_scene, "block", "direct", 20, 2);
  const Run    block_cg      = run(block_scene, "block", "CG-Jacobi", 20, 2);
  unsigned int sliding_steps = 0;
  for (const auto n : block_direct.sliding)
    sliding_steps += (n > 0);
  const double block_difference =
    relative_difference(block_cg.values, block_direct.values);
  std::cout << "sliding block, 20 steps (" << sliding_steps
            << " with sliding contacts): the same sliding contacts in every "
               "step: "
            << (block_cg.sliding == block_direct.sliding ? "yes" : "NO")
            << "; relative difference " << std::scientific
            << std::setprecision(1) << block_difference << std::defaultfloat
            << " (at most 1e-9)" << std::endl;
  check(sliding_steps > 10,
        "the block does not slide: no non-symmetric "
        "matrix was solved");
  check(block_cg.sliding == block_direct.sliding,
        "CG-Jacobi's sliding contacts against direct's");
  check(block_difference < 1e-9, "CG-Jacobi against direct on the block");

  // 3. A tridiagonal matrix 4, -1, -1 of 50 rows; then one diagonal entry
  // negative and one entry off the symmetry.
  const unsigned int     n = 50;
  DynamicSparsityPattern dsp(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
      dsp.add(i, j);
  SparsityPattern pattern;
  pattern.copy_from(dsp);
  SparseMatrix<double> matrix(pattern);
  Vector<double>       b(n), x, residual(n);
  for (unsigned int i = 0; i < n; ++i)
    {
      matrix.set(i, i, 4.);
      if (i > 0)
        matrix.set(i, i - 1, -1.);
      if (i + 1 < n)
        matrix.set(i, i + 1, -1.);
      b[i] = 1. + 0.1 * i;
    }
  const auto relative_residual = [&]() {
    matrix.residual(residual, x, b);
    return residual.l2_norm() / b.l2_norm();
  };
  ndda::JacobiCG solver;
  solver.initialize(matrix);
  const unsigned int spd_iterations = solver.solve(x, b, 1e-12);
  const double       spd_residual   = relative_residual();
  matrix.set(7, 7, -4.);
  matrix.set(20, 21, -2.5);
  solver.initialize(matrix);
  const unsigned int other_iterations = solver.solve(x, b, 1e-12);
  const double       other_residual   = relative_residual();
  std::cout << "50 rows: symmetric positive definite, CG "
            << (spd_residual <= 1e-12 ? "reaches" : "MISSES")
            << " 1e-12; a negative diagonal entry and an entry off the "
               "symmetry, BiCGStab "
            << (other_residual <= 1e-12 ? "reaches" : "MISSES") << " 1e-12"
            << std::endl;
  check(spd_iterations > 0 && spd_residual <= 1e-12, "CG on the SPD matrix");
  check(other_iterations > 0 && other_residual <= 1e-12,
        "BiCGStab on the indefinite, non-symmetric matrix");
  return 0;
}
