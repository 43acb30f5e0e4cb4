// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/parameters/entries.h>
#include <ndda/postprocess/output_parameters.h>

namespace ndda
{
  namespace parameters
  {
    using namespace dealii;

    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "",
                        Patterns::Anything(),
                        "Output directory; empty: output/<Scene name>/.");
      prm.declare_entry("Interval",
                        "0",
                        Patterns::Double(0.),
                        "Simulated time between graphical outputs (s); 0: "
                        "every step.");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "Write solution-NNNNN.vtu files and solution.pvd.");
      prm.declare_entry("Write hdf5",
                        "false",
                        Patterns::Bool(),
                        "Also write solution.h5 and solution.xdmf "
                        "(element degree 1 only).");
      prm.declare_entry("Measure points",
                        "",
                        Patterns::Anything(),
                        "Points 'x, y; x, y' (m) whose displacement, "
                        "velocity and stress histories are written to "
                        "measure_points.txt.");
      prm.declare_entry("Progress interval",
                        "2",
                        Patterns::Double(0.),
                        "Wall-clock seconds between progress lines.");
      prm.declare_entry(
        "Checkpoint interval",
        "0",
        Patterns::Double(0.),
        "Simulated time between checkpoints (s); 0: none. A checkpoint "
        "(checkpoint.ndda in the output directory, replaced each time) "
        "holds the whole state after a step, and one is written at the end "
        "of the run too; 'ndda --resume <output directory>' continues the "
        "run from it and ends in the same state, bit for bit, as the run "
        "would have without the interruption. Writing one starts the next "
        "step with a fresh factorization and neighbour list, so results "
        "differ from a run without checkpoints within the solver "
        "tolerance.");
      prm.leave_subsection();
    }



    void
    Output::parse_parameters(ParameterHandler  &prm,
                             const std::string &scene_name)
    {
      prm.enter_subsection("Output");
      directory = prm.get("Directory");
      if (directory.empty())
        directory = "output/" + scene_name;
      if (directory.back() != '/')
        directory += '/';
      interval   = prm.get_double("Interval");
      write_vtu  = prm.get_bool("Write vtu");
      write_hdf5 = prm.get_bool("Write hdf5");
      measure_points =
        parse_points(prm.get("Measure points"), "Output/Measure points");
      progress_interval   = prm.get_double("Progress interval");
      checkpoint_interval = prm.get_double("Checkpoint interval");
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace ndda
