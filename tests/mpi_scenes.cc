// SPDX-License-Identifier: GPL-3.0-or-later
//
// Scenes on several MPI processes (issue 19), run by ctest on two
// (`mpirun -np 2`), against the same scene on one process (each process
// runs that reference itself, on MPI_COMM_SELF):
//
//  - a contact scene (the default scene's first 40 steps: a cantilever
//    with a pre-existing crack whose faces close under a tip pulse, a
//    bolted weight, a spinning block) and a fracture scene (a beam
//    pressed against a floor block that cracks in every one of its first
//    6 steps, with sliding contacts, so that its matrices are not
//    symmetric);
//  - with Linear solver = direct every process solves the whole system
//    with the serial solver: the run must repeat the run on one process
//    to the bit (displacement, velocity, stresses, contact states, crack
//    edges);
//  - with MUMPS the processes solve together: the displacement must agree
//    with the one-process run to 1e-9 (relative, in the l2 norm), and the
//    cracked edges of every step must be the same, and in the contact
//    scene the contact states of every step. (In the fracture scene a
//    contact at its Coulomb limit slides in one run and sticks in the
//    other in some steps: MUMPS's round-off, which is not the serial
//    solver's and varies from run to run on two processes, decides it.
//    The number of such steps is printed, not required.)
//  - with CG-Jacobi (the contact scene's first 10 steps) the first
//    process solves, as with direct: the one-process run to the bit;
//  - in every run every process holds the same state, to the bit;
//  - run() on two processes writes each frame as one piece per process
//    and a .pvtu record naming them, the pieces holding every cell once,
//    and one HDF5 file (parallel HDF5) with every cell.

#include <deal.II/base/mpi.h>

#include <ndda/parallel/shared_mesh.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "tests.h"

using namespace ndda_tests;

const std::string fracture_scene = R"(
set Scene name = beam_on_floor
subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = 2e-4
  set End time        = 0.0012
end
subsection Materials
  set Names = rock
  subsection rock
    set Density          = 2600
    set Young's modulus  = 10e9
    set Poisson's ratio  = 0.25
    set Tensile strength = 1e5
    set Cohesion         = 3e5
    set Friction angle   = 30
    set Fracture         = true
  end
end
subsection Geometry
  set Blocks = beam, floor
  subsection beam
    set Outer boundary = 0, 0.1; 2, 0.1; 2, 0.4; 0, 0.4
    set Material  = rock
    set Mesh size = 0.1
  end
  subsection floor
    set Outer boundary = 1, -0.2; 3, -0.2; 3, 0.1; 1, 0.1
    set Material  = rock
    set Mesh size = 0.15
  end
end
subsection Loads
  set Gravity = 0; -9.81
  set Line loads = push
  subsection push
    set Segment = 2, 0.1, 2, 0.4
    set Type    = traction
    set Value   = 0; -2e6 * (t < 0.004)
  end
end
subsection Boundary conditions
  set Names = clamp, base
  subsection clamp
    set Type     = fixed
    set Segments = 0, 0.1, 0, 0.4
  end
  subsection base
    set Type     = fixed
    set Segments = 1, -0.2, 3, -0.2
  end
end
subsection Output
  set Write vtu = false
end
)";

namespace
{
  using namespace dealii;

  /** What a run gives, step after step and at its end. */
  struct Run
  {
    /// Per step: closed and sliding contacts, cracked edges.
    std::vector<std::array<unsigned int, 3>> steps;
    std::vector<std::array<unsigned int, 2>> crack_edges;
    Vector<double>                           displacement;
    /// Displacement, velocity and every stress component, in one list.
    std::vector<double> state;
    /// At the end: the dofs of every cell, cell after cell.
    std::vector<types::global_dof_index> cell_dofs;
    /// At the end: whether the triangulation is shared among the
    /// processes, and whether the cells and dofs each owns, by deal.II's
    /// account, are OwnedCells' range and add up to all.
    bool shared       = false;
    bool owners_agree = false;
  };

  Run
  run(const std::string &text,
      const std::string &name,
      const std::string &solver,
      const MPI_Comm     communicator)
  {
    auto parameters =
      read_parameters(text + "subsection Control\n  set Linear solver = " +
                        solver + "\nend\n",
                      name);
    ndda::Simulator<2> simulator(parameters, nullptr, communicator);
    simulator.setup();
    Run result;
    while (simulator.get_time() < parameters.control.end_time * (1. - 1e-12))
      {
        simulator.do_time_step();
        const auto &contacts = simulator.get_contacts().get_statistics();
        result.steps.push_back({{contacts.n_closed,
                                 contacts.n_sliding,
                                 simulator.get_n_cracked_edges()}});
      }
    result.crack_edges  = simulator.get_mesh().get_block_mesh().crack_edges;
    result.displacement = simulator.get_displacement();
    const auto &v       = simulator.get_velocity();
    result.state.assign(result.displacement.begin(), result.displacement.end());
    result.state.insert(result.state.end(), v.begin(), v.end());
    for (const auto &sigma : simulator.get_stresses().values())
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          result.state.push_back(sigma[i][j]);

    const auto &dof_handler = simulator.get_dof_handler();
    const auto &tria        = dof_handler.get_triangulation();
    const auto &owned       = simulator.get_discretization().owned_cells;
    std::vector<types::global_dof_index> dofs;
    bool                                 owned_range = true;
    unsigned int                         n_owned     = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        dofs.resize(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        result.cell_dofs.insert(result.cell_dofs.end(),
                                dofs.begin(),
                                dofs.end());
        const auto c = cell->active_cell_index();
        n_owned += cell->is_locally_owned() ? 1 : 0;
        owned_range = owned_range && cell->is_locally_owned() ==
                                       (c >= owned.begin() && c < owned.end());
      }
    result.shared = ndda::is_shared(tria);
    result.owners_agree =
      Utilities::MPI::min(owned_range ? 1u : 0u, communicator) == 1 &&
      Utilities::MPI::sum(n_owned, communicator) == tria.n_active_cells() &&
      Utilities::MPI::sum(dof_handler.n_locally_owned_dofs(), communicator) ==
        dof_handler.n_dofs();
    return result;
  }

  double
  relative_difference(const Vector<double> &x, const Vector<double> &y)
  {
    Vector<double> d(x);
    d -= y;
    return d.l2_norm() / y.l2_norm();
  }

  /**
   * Run @p text on one process (the reference) and on all of them with
   * the direct solver and with MUMPS; compare.
   */
  void
  compare(const std::string  &text,
          const std::string  &name,
          const bool          same_contact_states,
          ConditionalOStream &out,
          ConditionalOStream &diagnostics)
  {
    const MPI_Comm world     = MPI_COMM_WORLD;
    const Run      reference = run(text, name, "direct", MPI_COMM_SELF);
    unsigned int   contacts = 0, cracks = 0;
    for (const auto &step : reference.steps)
      {
        contacts = std::max(contacts, step[0] + step[1]);
        cracks   = std::max(cracks, step[2]);
      }
    out << name << ": " << reference.steps.size() << " steps, "
        << (contacts > 0 ? "contacts" : "no contacts") << ", "
        << (cracks > 0 ? "cracks" : "no cracks") << std::endl;
    diagnostics << name << ": at most " << contacts << " contacts, " << cracks
                << " cracked edges" << std::endl;

    const Run direct = run(text, name, "direct", world);
    check(same_on_every_process(direct.state, world),
          name + ", direct: every process holds the same state");
    check(direct.state == reference.state,
          name + ", direct: the state is the one-process state, bit for bit");
    check(direct.steps == reference.steps &&
            direct.crack_edges == reference.crack_edges,
          name + ", direct: the same contact states and cracks");
    // The mesh on several processes: deal.II's shared triangulation, each
    // process owning OwnedCells' range, the dofs numbered as on one.
    check(!reference.shared && reference.owners_agree,
          name + ", one process: a plain triangulation that owns every cell");
    check(direct.shared == (Utilities::MPI::n_mpi_processes(world) > 1) &&
            direct.owners_agree,
          name + ", direct: a shared triangulation whose owners are "
                 "OwnedCells' ranges");
    check(direct.cell_dofs == reference.cell_dofs,
          name + ", direct: every cell's dofs numbered as on one process");
    out << name << ", direct solver on every process: the one-process run "
        << "to the bit" << std::endl;

    const Run mumps = run(text, name, "MUMPS", world);
    check(same_on_every_process(mumps.state, world),
          name + ", MUMPS: every process holds the same state");
    const double difference =
      relative_difference(mumps.displacement, reference.displacement);
    diagnostics << name << ", MUMPS against one process: " << difference
                << std::endl;
    check(difference <= 1e-9,
          name + ", MUMPS: the displacement agrees to 1e-9");
    // The contact states: each step's closed and sliding contacts. A
    // contact at its Coulomb limit may slide in one run and stick in the
    // other (MUMPS's round-off is not the serial solver's): with
    // @p same_contact_states false they are counted, not required.
    unsigned int differing_steps = 0;
    check(mumps.steps.size() == reference.steps.size(),
          name + ", MUMPS: as many steps");
    for (unsigned int s = 0; s < reference.steps.size(); ++s)
      {
        check(mumps.steps[s][2] == reference.steps[s][2],
              name + ", MUMPS: the same cracked edges in every step");
        if (mumps.steps[s] != reference.steps[s])
          {
            if (differing_steps == 0)
              diagnostics << name << ", MUMPS: step " << s + 1
                          << " closed/sliding " << mumps.steps[s][0] << '/'
                          << mumps.steps[s][1] << " against "
                          << reference.steps[s][0] << '/'
                          << reference.steps[s][1] << std::endl;
            ++differing_steps;
          }
      }
    check(mumps.crack_edges == reference.crack_edges,
          name + ", MUMPS: the same crack edges");
    diagnostics << name << ", MUMPS: " << differing_steps << " of "
                << reference.steps.size() << " steps with other contact states"
                << std::endl;
    if (same_contact_states)
      check(differing_steps == 0,
            name + ", MUMPS: the same contact states in every step");
    out << name << ", MUMPS on all processes: displacement to 1e-9, the "
        << "same cracks" << (same_contact_states ? " and contact states" : "")
        << " in every step" << std::endl;
  }



  /** The value of attribute @p name in the first line of @p file that has it.
   */
  unsigned int
  attribute(const std::string &file, const std::string &name)
  {
    std::ifstream    in(file);
    std::string      line;
    const std::regex pattern(name + "=\"([0-9]+)\"");
    std::smatch      match;
    while (std::getline(in, line))
      if (std::regex_search(line, match, pattern))
        return std::stoul(match[1].str());
    return 0;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   world = MPI_COMM_WORLD;
  const unsigned int n_processes = Utilities::MPI::n_mpi_processes(world);
  const bool         first       = Utilities::MPI::this_mpi_process(world) == 0;
  ConditionalOStream out(std::cout, first);
  ConditionalOStream diagnostics(std::cerr, first);
  out << "processes: " << (n_processes > 1 ? "several" : "one") << std::endl;

  std::string contact_scene = read_example("default");
  contact_scene             = set_entry(contact_scene, "End time", "0.04");
  compare(contact_scene, "default", true, out, diagnostics);
  compare(fracture_scene, "beam_on_floor", false, out, diagnostics);

  // CG-Jacobi is solved by the first process alone, as the direct solver
  // is: on several processes it repeats the one-process run to the bit.
  // (10 steps: its BiCGStab takes several hundred iterations a step.)
  {
    const std::string short_scene =
      set_entry(contact_scene, "End time", "0.01");
    const Run one = run(short_scene, "default", "CG-Jacobi", MPI_COMM_SELF);
    const Run all = run(short_scene, "default", "CG-Jacobi", world);
    check(same_on_every_process(all.state, world),
          "default, CG-Jacobi: every process holds the same state");
    check(all.state == one.state && all.steps == one.steps,
          "default, CG-Jacobi: the one-process run to the bit");
    out << "default, CG-Jacobi on the first process: the one-process run to "
           "the bit"
        << std::endl;
  }

  // Frames on several processes: one piece each, and a record.
  {
    std::string text = set_entry(contact_scene, "End time", "0.02");
    text += "subsection Output\n  set Directory = output-pieces\n"
            "  set Write hdf5 = true\nend\n";
    auto parameters = read_parameters(text, "default");
    // The run's console output goes to the log, not into this test's.
    std::ostringstream console;
    auto *const        cout_buffer = std::cout.rdbuf(console.rdbuf());
    ndda::Simulator<2> simulator(parameters, nullptr, world);
    simulator.run();
    std::cout.rdbuf(cout_buffer);
    check(console.str().find("on " + std::to_string(n_processes) +
                             " MPI processes") != std::string::npos ||
            n_processes == 1 || !first,
          "the run says on how many processes it runs");
    const unsigned int n_cells =
      simulator.get_mesh().get_triangulation().n_active_cells();
    MPI_Barrier(world);
    const std::string directory = "output-pieces/";
    if (n_processes > 1)
      {
        const std::string record = directory + "solution-00001.pvtu";
        check(std::filesystem::exists(record), "a .pvtu record per frame");
        std::ifstream in(record);
        std::string   text_of_record((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
        unsigned int  cells = 0;
        for (unsigned int p = 0; p < n_processes; ++p)
          {
            const std::string piece =
              "solution-00001." +
              Utilities::int_to_string(p,
                                       Utilities::needed_digits(n_processes -
                                                                1)) +
              ".vtu";
            check(text_of_record.find("\"" + piece + "\"") != std::string::npos,
                  "the record names piece " + piece);
            const unsigned int piece_cells =
              attribute(directory + piece, "NumberOfCells");
            check(piece_cells > 0, "every piece holds cells");
            cells += piece_cells;
          }
        check(cells == n_cells, "the pieces hold every cell once");
        check(!std::filesystem::exists(directory + "solution-00001.vtu"),
              "no whole-scene frame beside the pieces");
      }
    else
      check(std::filesystem::exists(directory + "solution-00001.vtu"),
            "one process writes a whole frame");
    check(std::filesystem::exists(directory + "statistics"),
          "the statistics are written");
    // One HDF5 file a frame from all processes, every cell once.
    {
      std::ifstream in(directory + "solution.xdmf");
      std::string   xdmf((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
      check(std::filesystem::exists(directory + "solution-00001.h5") &&
              xdmf.find("Dimensions=\"" + std::to_string(n_cells) + " 3\"") !=
                std::string::npos,
            "one HDF5 file per frame with every cell");
    }
    out << "frames: one piece per process and a .pvtu record, one HDF5 "
        << "file, every cell once" << std::endl;
  }
  return 0;
}
