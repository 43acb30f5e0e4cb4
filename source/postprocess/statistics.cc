// SPDX-License-Identifier: GPL-3.0-or-later
//
// The built-in groups of statistics columns (one row per time step).

#include <ndda/postprocess/postprocessor.h>
#include <ndda/simulator.h>

namespace ndda
{
  namespace postprocess
  {
    /** Step number, time, step size, cuts, solver figures. */
    class TimeStepStatistics : public Postprocessor
    {
    public:
      void
      add_statistics(const Simulator<2> &simulator,
                     StatisticsTable    &statistics) const override
      {
        const auto &step = simulator.get_step_report();
        statistics.add_value("Time step number", simulator.get_step_number());
        add_scientific(statistics, "Time (s)", simulator.get_time());
        add_scientific(statistics, "Time step size (s)", step.dt);
        statistics.add_value("Step cuts", step.cuts);
        statistics.add_value("Solver iterations", step.solver_iterations);
        statistics.add_value("Matrix builds", step.matrix_builds);
        add_scientific(statistics, "Max increment (m)", step.max_increment);
      }
    };



    /** Kinetic and strain energy, work of the loads, energy gain. */
    class EnergyStatistics : public Postprocessor
    {
    public:
      void
      add_statistics(const Simulator<2> &simulator,
                     StatisticsTable    &statistics) const override
      {
        // Each energy once: the kinetic energy is a product with the
        // whole mass matrix.
        const double kinetic = simulator.kinetic_energy();
        const double strain  = simulator.strain_energy();
        add_scientific(statistics, "Kinetic energy (J)", kinetic);
        add_scientific(statistics, "Strain energy (J)", strain);
        add_scientific(statistics,
                       "Work of loads (J)",
                       simulator.work_of_loads());
        add_scientific(statistics,
                       "Work of prescribed motion (J)",
                       simulator.work_of_prescribed_motion());
        add_scientific(statistics,
                       "Energy gain (J)",
                       simulator.energy_error(kinetic, strain));
        if (simulator.has_viscosity())
          add_scientific(statistics,
                         "Viscous dissipation (J)",
                         simulator.viscous_dissipation());
        add_scientific(statistics,
                       "Numerical energy (J)",
                       simulator.numerical_energy(kinetic, strain));
      }
    };



    /** Crack events, cracked and failing edges (scenes with fracture). */
    class FractureStatistics : public Postprocessor
    {
    public:
      void
      add_statistics(const Simulator<2> &simulator,
                     StatisticsTable    &statistics) const override
      {
        const auto &step = simulator.get_step_report();
        if (!step.fracture)
          return;
        if (simulator.get_parameters().fracture.split_edges)
          {
            statistics.add_value("Crack events", step.crack_events);
            statistics.add_value("Cracked edges",
                                 simulator.get_n_cracked_edges());
            statistics.add_value("Crack limit hit",
                                 step.crack_limit_hit ? 1 : 0);
          }
        statistics.add_value("Failing edges", step.failing_edges);
      }
    };



    /** Open-close iterations, contact counts and energies. */
    class ContactColumns : public Postprocessor
    {
    public:
      void
      add_statistics(const Simulator<2> &simulator,
                     StatisticsTable    &statistics) const override
      {
        if (!simulator.get_parameters().contact.enabled)
          return;
        const auto &contacts = simulator.get_contacts();
        const auto &c        = contacts.get_statistics();
        statistics.add_value("Open-close iterations", c.n_iterations);
        statistics.add_value("Open-close cuts",
                             simulator.get_step_report().open_close_cuts);
        statistics.add_value("Contact candidates", c.n_contacts);
        add_scientific(statistics,
                       "Detection distance (m)",
                       simulator.get_detection_distance().get());
        statistics.add_value("Closed contacts", c.n_closed);
        statistics.add_value("Sliding contacts", c.n_sliding);
        statistics.add_value("Vertex springs", c.n_vertex_springs);
        statistics.add_value("Bonded contacts", c.n_bonded);
        add_scientific(statistics, "Max penetration (m)", c.max_penetration);
        add_scientific(statistics, "Contact energy (J)", c.spring_energy);
        add_scientific(statistics, "Contact dissipation (J)", c.dissipation);
        add_scientific(statistics,
                       "Friction dissipation (J)",
                       c.friction_dissipation);
        add_scientific(statistics,
                       "Normal stiffness (N/m)",
                       contacts.get_settings().normal_stiffness);
      }
    };



    /**
     * The wall time of each step. Not in the default list: a statistics
     * file without it is the same in every run, so it can be pinned
     * (a .prm test with an .output file); the log has the run's wall time.
     */
    class WallTime : public Postprocessor
    {
    public:
      void
      add_statistics(const Simulator<2> &simulator,
                     StatisticsTable    &statistics) const override
      {
        statistics.add_value("Wall time per step (s)",
                             simulator.last_step_wall_time());
      }
    };



    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      TimeStepStatistics,
      "time step",
      "Statistics columns 'Time step number', 'Time (s)', 'Time step size "
      "(s)', 'Step cuts', 'Solver iterations' (of the last solve; 0 for a "
      "solve with a fresh factorization), 'Matrix builds' (so far) and "
      "'Max increment (m)'.")
    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      EnergyStatistics,
      "energy",
      "Statistics columns 'Kinetic energy (J)', 'Strain energy (J)', 'Work "
      "of loads (J)', 'Work of prescribed motion (J)' (the reactions of "
      "moving supports times their motion; not counted with the penalty "
      "constraint method), 'Energy gain (J)' (kinetic + strain + contact "
      "spring energy - work of the loads - work of prescribed motion - "
      "initial kinetic energy), with viscous materials 'Viscous dissipation "
      "(J)', and 'Numerical energy (J)': the gain plus the friction and "
      "viscous dissipation, the energy the integrator gave (positive) or "
      "took (negative), contact switching included (doc/theory.md, "
      "'Energy balance').")
    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      FractureStatistics,
      "fracture",
      "With fracturing materials, statistics columns 'Crack events' and "
      "'Cracked edges' (so far), 'Crack limit hit' (with Split edges) and "
      "'Failing edges' (in the step's last check).")
    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      ContactColumns,
      "contact",
      "With contact, statistics columns 'Open-close iterations', "
      "'Open-close cuts', 'Contact candidates', 'Detection distance (m)', "
      "'Closed contacts', "
      "'Sliding contacts', 'Vertex springs', 'Bonded contacts', 'Max "
      "penetration (m)', 'Contact energy (J)', 'Contact dissipation (J)' "
      "(taken out by the contacts so far: friction and the integrator's "
      "contact switching), 'Friction dissipation (J)' (its friction part) "
      "and 'Normal stiffness (N/m)'.")
    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      WallTime,
      "wall time",
      "Statistics column 'Wall time per step (s)'. Leave it out of the list "
      "(the default) for a statistics file that is the same in every run.")
  } // namespace postprocess
} // namespace ndda
