// SPDX-License-Identifier: GPL-3.0-or-later
//
// A rebuild of the element matrices of some cells (those that moved beyond
// Control/Matrix update tolerance) sums again only the rows of the global
// matrices that those cells touch (LinearSystem::assemble() with the
// changed cells). Those rows must come out bit for bit as a full assembly
// gives them, so that no result depends on which way the matrices were
// assembled. A beam, clamped at its left end, swings under gravity (with
// viscous damping, so that the damping matrix is rebuilt too) at a small
// update tolerance; after every step that rebuilt some but not all cells,
// K, M and C are compared with a full sum over the cells, entry by entry,
// for P1 and P2. M is stored without its zero entries (those coupling a
// node's x and y dofs): every nonzero entry of the full sum must be in it.

#include <deal.II/lac/sparse_matrix.h>

#include "tests.h"

using namespace ndda_tests;

const std::string scene = R"(
subsection Control
  set Analysis type = dynamic
  set Time step = 2e-3
  set End time = 1
  set Element degree = {degree}
  set Matrix update tolerance = 1e-4
end
subsection Materials
  set Names = rock
  set Plane condition = plane stress
  subsection rock
    set Young's modulus = 1e8
    set Poisson's ratio = 0.25
    set Density = 2000
    set Viscosity = 1e4
  end
end
subsection Geometry
  set Blocks = beam
  subsection beam
    set Outer boundary = 0, 0; 4, 0; 4, 0.5; 0, 0.5
    set Material = rock
    set Mesh size = 0.25
  end
end
subsection Loads
  set Gravity = 0; -9.81
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
  /**
   * Add to @p full the full sum of the element matrices (@p element_matrix
   * of each cell, on its dofs from @p dof_map, times @p factor of the
   * cell).
   */
  template <typename ElementMatrix, typename Factor>
  void
  add_full_sum(dealii::SparseMatrix<double> &full,
               const ndda::DofMap           &dof_map,
               const ElementMatrix          &element_matrix,
               const Factor                 &factor)
  {
    using namespace dealii;
    const unsigned int                   n = dof_map.dofs_per_cell;
    std::vector<types::global_dof_index> dofs(n);
    for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
      {
        std::copy(dof_map.dofs_of_cell(c),
                  dof_map.dofs_of_cell(c) + n,
                  dofs.begin());
        const auto m = element_matrix(c);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            full.add(dofs[i], dofs[j], factor(c) * m(i, j));
      }
  }

  /**
   * The number of entries of @p matrix that differ from the full sum of
   * the element matrices (add_full_sum()).
   */
  template <typename ElementMatrix, typename Factor>
  unsigned int
  entries_differing(const dealii::SparseMatrix<double> &matrix,
                    const ndda::DofMap                 &dof_map,
                    const ElementMatrix                &element_matrix,
                    const Factor                       &factor)
  {
    using namespace dealii;
    SparseMatrix<double> full(matrix.get_sparsity_pattern());
    add_full_sum(full, dof_map, element_matrix, factor);
    unsigned int differing = 0;
    for (unsigned int r = 0; r < matrix.m(); ++r)
      {
        auto a = matrix.begin(r);
        auto b = full.begin(r);
        for (; a != matrix.end(r); ++a, ++b)
          if (a->value() != b->value())
            ++differing;
      }
    return differing;
  }

  /**
   * The number of nonzero entries of the full sum of the element mass
   * matrices (on the system's pattern @p pattern) that the mass matrix
   * @p mass, stored without its zeros, lacks or holds with another value.
   */
  unsigned int
  mass_entries_missing(const dealii::SparseMatrix<double> &mass,
                       const dealii::SparsityPattern      &pattern,
                       const ndda::DofMap                 &dof_map,
                       const ndda::ElementCache<2>        &cache)
  {
    using namespace dealii;
    SparseMatrix<double> full(pattern);
    add_full_sum(
      full,
      dof_map,
      [&](unsigned int c) { return cache[c].mass; },
      [](unsigned int) { return 1.; });
    unsigned int missing = 0;
    for (unsigned int r = 0; r < full.m(); ++r)
      for (auto entry = full.begin(r); entry != full.end(r); ++entry)
        {
          const double value = entry->value();
          if (value != 0. && mass.el(r, entry->column()) != value)
            ++missing;
        }
    return missing;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  for (const unsigned int degree : {1u, 2u})
    {
      auto parameters =
        read_parameters(substitute(scene, {{"degree", std::to_string(degree)}}),
                        "beam");
      ndda::Simulator<2> simulator(parameters);
      simulator.setup();
      const auto        &fem = simulator.get_discretization();
      const unsigned int n_cells =
        simulator.get_mesh().get_triangulation().n_active_cells();
      unsigned int partial = 0, differing = 0;
      std::size_t  mass_entries = 0, pattern_entries = 0;
      for (unsigned int step = 0; step < 150; ++step)
        {
          simulator.do_time_step();
          const unsigned int rebuilt =
            fem.element_cache.get_computed_cells().size();
          if (step == 0 || rebuilt == 0 || 2 * rebuilt >= n_cells)
            continue;
          ++partial;
          const auto &system = fem.linear_system;
          const auto &cache  = fem.element_cache;
          const auto  one    = [](unsigned int) { return 1.; };
          differing += entries_differing(
            system.get_stiffness_matrix(),
            fem.dof_map,
            [&](unsigned int c) -> ndda::ElementCache<2>::CellMatrix {
              return cache[c].stiffness;
            },
            one);
          const auto mass = [&](unsigned int c) { return cache[c].mass; };
          differing +=
            entries_differing(system.get_mass_matrix(), fem.dof_map, mass, one);
          // M is stored without its zeros: every nonzero of the full sum
          // is there.
          differing += mass_entries_missing(
            system.get_mass_matrix(),
            system.get_stiffness_matrix().get_sparsity_pattern(),
            fem.dof_map,
            cache);
          mass_entries    = system.get_mass_matrix().n_nonzero_elements();
          pattern_entries = system.get_stiffness_matrix().n_nonzero_elements();
          differing +=
            entries_differing(system.get_damping_matrix(),
                              fem.dof_map,
                              mass,
                              [&](unsigned int c) {
                                return cache[c].viscosity_over_density;
                              });
        }
      std::cout << "P" << degree << ": steps that rebuilt some cells "
                << (partial >= 10 ? "10 or more" : std::to_string(partial))
                << ", entries of K, M, C that differ from a full assembly "
                << differing << std::endl;
      std::cout << "P" << degree << ": M stored with "
                << (2 * mass_entries <= pattern_entries ? "at most half" :
                                                          "more than half")
                << " the entries of the system's pattern" << std::endl;
      check(partial >= 10, "too few partial rebuilds to test");
      check(differing == 0, "a partial assembly differs from a full one");
    }
  std::cout << "OK" << std::endl;
}
