// SPDX-License-Identifier: GPL-3.0-or-later
//
// The compact system (rigid and affine blocks under a direct solver) keeps
// the contact couplings in its own pattern alone: LinearSystem builds it
// from the element part kept at reinit() and each (vertex, cell) coupling
// expanded through the blocks' lines, and leaves it as it is when the new
// couplings of a step expand to entries it already has. Its entries must
// be exactly those of the whole pattern (elements and contact couplings
// on every dof) condensed with the constraints and restricted to the free
// dofs: an entry missing there would be written out of bounds, an entry
// too many would only cost fill.
//
// A meshed block slides across a pile of rigid bricks, and an affine block
// slides into the pile along the rigid ground; after every step the
// compact pattern is compared with the whole pattern condensed directly,
// here from deal.II's own sparsity and condensation functions. The test
// also checks that both ways of taking new couplings ran: a pattern built
// anew, and new couplings that the pattern already held.

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>

#include "tests.h"

using namespace ndda_tests;

const std::string scene = R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = 2e-3
  set End time        = 0.3
  set Linear solver   = direct
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
    set Friction angle = 10
  end
end
subsection Geometry
  set Blocks  = ground, slider, pusher
  set Regions = pile
  subsection ground
    set Outer boundary = -1, -0.5; 7, -0.5; 7, 0; -1, 0
    set Material = rock
    set Mesh size = 2
  end
  subsection pile
    set Outer boundary = 0, 0; 3, 0; 3, 1; 0, 1
    set Joints = 0, 0.5, 3, 0.5; 1, 0, 1, 0.5; 2, 0, 2, 0.5; \
                 0.5, 0.5, 0.5, 1; 1.5, 0.5, 1.5, 1; 2.5, 0.5, 2.5, 1
    set Material = rock
    set Mesh size = 0.5
  end
  subsection slider
    set Outer boundary = 0.1, 1; 1.1, 1; 1.1, 1.3; 0.1, 1.3
    set Material = rock
    set Kinematics = meshed
    set Mesh size = 0.2
    set Initial velocity = 6; 0
  end
  subsection pusher
    set Outer boundary = 3.2, 0; 4.2, 0; 4.2, 0.6; 3.2, 0.6
    set Material = rock
    set Kinematics = affine
    set Mesh size = 0.3
    set Initial velocity = -3; 0
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = bed
  subsection bed
    set Type = fixed
    set Segments = -1, -0.5, 7, -0.5
  end
end
)";

namespace
{
  /**
   * The number of entries in which the compact pattern of @p fem differs
   * from the whole pattern (the cells' couplings and the contact
   * couplings on every dof) condensed with the constraints and restricted
   * to the free dofs: entries either has and the other lacks.
   */
  unsigned int
  entries_differing(const ndda::scene::Discretization &fem)
  {
    using namespace dealii;
    const auto &system = fem.linear_system;
    const auto &affine = fem.constraints.affine_constraints();
    const auto &dofs   = fem.dof_map;

    DynamicSparsityPattern whole(fem.dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(fem.dof_handler, whole, affine, true);
    for (const auto &[vertex, cell] : system.get_contact_couplings())
      for (const auto i : dofs.vertex_dofs[vertex])
        for (unsigned int k = 0; k < dofs.dofs_per_cell; ++k)
          {
            const auto j = dofs.dofs_of_cell(cell)[k];
            whole.add(i, j);
            whole.add(j, i);
          }
    affine.condense(whole);

    const auto                          &free_dofs = system.get_free_dofs();
    std::vector<types::global_dof_index> compact_index(
      fem.dof_handler.n_dofs(), numbers::invalid_dof_index);
    for (unsigned int r = 0; r < free_dofs.size(); ++r)
      compact_index[free_dofs[r]] = r;

    const auto                          &compact = system.get_compact_pattern();
    unsigned int                         differing = 0;
    std::vector<types::global_dof_index> expected, held;
    for (unsigned int r = 0; r < free_dofs.size(); ++r)
      {
        expected.clear();
        for (auto entry = whole.begin(free_dofs[r]);
             entry != whole.end(free_dofs[r]);
             ++entry)
          if (compact_index[entry->column()] != numbers::invalid_dof_index)
            expected.push_back(compact_index[entry->column()]);
        std::sort(expected.begin(), expected.end());
        held.clear();
        for (auto entry = compact.begin(r); entry != compact.end(r); ++entry)
          held.push_back(entry->column());
        std::sort(held.begin(), held.end());
        std::vector<types::global_dof_index> either;
        std::set_symmetric_difference(expected.begin(),
                                      expected.end(),
                                      held.begin(),
                                      held.end(),
                                      std::back_inserter(either));
        differing += either.size();
      }
    return differing;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  auto               parameters = read_parameters(scene, "compact_pattern");
  ndda::Simulator<2> simulator(parameters);
  simulator.setup();
  const auto &fem    = simulator.get_discretization();
  const auto &system = fem.linear_system;
  check(system.is_compact(), "the scene's system is not compact");

  unsigned int steps = 0, differing = 0, built = 0, held = 0;
  auto         couplings = system.get_contact_couplings();
  auto         builds    = system.n_compact_pattern_builds();
  while (simulator.get_time() < 0.3 - 1e-12)
    {
      simulator.do_time_step();
      ++steps;
      differing += entries_differing(fem);
      if (system.get_contact_couplings() != couplings)
        {
          if (system.n_compact_pattern_builds() != builds)
            ++built;
          else
            ++held;
        }
      couplings = system.get_contact_couplings();
      builds    = system.n_compact_pattern_builds();
    }
  const auto at_least = [](const unsigned int n, const unsigned int least) {
    return n >= least ? std::to_string(least) + " or more" : std::to_string(n);
  };
  std::cout << "steps " << steps << ", entries of the compact pattern that "
            << "differ from the whole pattern condensed " << differing
            << std::endl;
  std::cout << "steps with new couplings: pattern built anew "
            << at_least(built, 3) << ", pattern kept " << at_least(held, 3)
            << std::endl;
  check(differing == 0,
        "the compact pattern differs from the whole pattern condensed");
  check(built >= 3 && held >= 3,
        "the scene did not exercise both ways of taking new couplings");
  std::cout << "OK" << std::endl;
}
