// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_time_time_integrator_h
#define ndda_time_time_integrator_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/base/plugin_registry.h>

#include <memory>
#include <string>

namespace ndda
{
  /**
   * Time integration: how a step's increment d of the displacement turns
   * into the linear system of the step and into the velocity and
   * acceleration at its end.
   *
   * @ingroup time
   */
  namespace time
  {
    using dealii::ParameterHandler;
    using dealii::SparseMatrix;
    using dealii::Vector;

    /**
     * The kinematic state a time integrator carries from step to step, as
     * dof vectors: the velocity v and the inertia force M a (the mass
     * matrix times the acceleration; kept as a force so that contact forces
     * can be taken out of it without a mass solve, and so that it carries
     * over a crack through the lumped mass). A scheme whose forces act at
     * a point inside the step (generalized-α) keeps there the force at the
     * step's start instead, f_ext - f_int + contact forces, which is M a
     * wherever the equation of motion holds at the step's ends (Newmark),
     * and keeps the acceleration itself as a third vector; the others leave
     * @p acceleration empty.
     */
    struct KinematicState
    {
      Vector<double> velocity;
      Vector<double> inertia_force;
      Vector<double> acceleration;
      /// True before a run's first step when the scheme keeps the
      /// acceleration: it has no acceleration of its own yet, and finds one
      /// with the first step (generalized-α takes it constant over that
      /// step, GeneralizedAlpha). update() sets it to false.
      bool starting = false;
    };

    /**
     * Interface of a time integrator. Every step solves
     *
     *   (K + c_M M + c_C C + contact springs) d
     *       = f_ext(t1) - f_int + inertia terms + contact forces,
     *
     * for the increment d (thesis 3.15; doc/theory.md derives both built-in
     * schemes). Everything that differs between integrators is decided
     * here: the mass and damping coefficients, the inertia terms of the
     * right-hand side, whether contact forces are averaged over the step,
     * whether the run needs M a at t = 0, and the velocity and inertia force
     * at the step's end.
     *
     * An integrator is a plugin (NDDA_REGISTER_PLUGIN with this interface):
     * `set Time integrator = name` in `subsection Control` selects it, and
     * its own entries live in `subsection Control / subsection <name>`.
     * `Analysis type = static` and `quasi-static` are not schemes of their
     * own: time::create_time_integrator() wraps (static) or replaces
     * (quasi-static) the selected scheme.
     */
    class TimeIntegrator
    {
    public:
      virtual ~TimeIntegrator() = default;

      /**
       * Declare the integrator's parameters (its subsection is entered).
       * The default declares none; a scheme with parameters hides it with
       * its own.
       */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read the integrator's parameters (its subsection is entered). */
      virtual void
      parse_parameters(ParameterHandler &prm);

      /** c_M: the mass matrix's factor in the step's matrix (1/s^2). */
      virtual double
      mass_coefficient(const double dt) const = 0;

      /**
       * c_M of a run's first step, taken when KinematicState::starting is
       * set (step_mass_coefficient()). The default is mass_coefficient().
       */
      virtual double
      first_step_mass_coefficient(const double dt) const;

      /** c_M of a step of length @p dt from the state @p start. */
      double
      step_mass_coefficient(const double dt, const KinematicState &start) const
      {
        return start.starting ? first_step_mass_coefficient(dt) :
                                mass_coefficient(dt);
      }

      /**
       * c_C: the damping (viscosity) matrix's factor in the step's matrix
       * (1/s). The default 1/dt makes the viscous force C d / dt that of
       * the step's mean velocity.
       */
      virtual double
      damping_coefficient(const double dt) const;

      /** Add the inertia terms of the step's start state to @p rhs. */
      virtual void
      add_inertia_terms(const SparseMatrix<double> &mass,
                        const KinematicState       &start,
                        const double                dt,
                        Vector<double>             &rhs) const = 0;

      /**
       * The weight w of the contact forces at the step's start: they act as
       * w times their start value plus 1 - w times their end value (0: at
       * the end, Shi's scheme and the default; 1/2: the mean, Newmark's
       * average acceleration; alpha_f: generalized-α). With w > 0 the
       * contacts correct the start force for contacts that open or close
       * within the step (contact::ContactHandler::newmark_correction()),
       * and that correction enters the right-hand side with the weight
       * w / (1 - w).
       */
      virtual double
      contact_start_weight() const;

      /** Whether contact_start_weight() is not zero. */
      bool
      averages_contact_forces() const
      {
        return contact_start_weight() > 0.;
      }

      /** Whether the run starts by solving M a0 = f_ext(0) - f_int. */
      virtual bool
      needs_initial_acceleration() const;

      /**
       * Whether the scheme keeps the acceleration as a vector of its own
       * (KinematicState::acceleration): the run starts with
       * KinematicState::starting set, the scheme finding its acceleration
       * with the first step, and turns, transfers and fits it with the
       * velocity.
       */
      virtual bool
      keeps_acceleration() const;

      /**
       * The velocity and inertia force at the end of a step of length
       * @p dt with increment @p d, from those at its start (@p state is
       * overwritten). @p contact_correction is what the contacts changed in
       * the inertia force of the step (zero unless
       * averages_contact_forces()).
       */
      virtual void
      update(const Vector<double>       &d,
             const double                dt,
             const SparseMatrix<double> &mass,
             const Vector<double>       &contact_correction,
             KinematicState             &state) const = 0;

      /** For messages (PluginRegistry). */
      static const char *
      plugin_kind()
      {
        return "time integrator";
      }

      static const char *
      plugin_kinds()
      {
        return "time integrators";
      }

      static const char *
      selection_entry()
      {
        return "Control/Time integrator";
      }

      /** Keep the built-in integrators in every program. */
      static void
      link_builtin_plugins();
    };

    /** The registry of time integrators. */
    using TimeIntegratorRegistry = PluginRegistry<TimeIntegrator>;

    /** `Control/Analysis type`. */
    enum class AnalysisType
    {
      /// Thesis 3.7: DDA statics keep the inertia terms but start every
      /// step at rest.
      static_analysis,
      /// The velocity carries over from step to step.
      dynamic_analysis,
      /// No inertia: every step solves equilibrium K d = f.
      quasi_static
    };

    /**
     * The integrator of a scene: the scheme @p scheme (already created and
     * with its parameters read) for a dynamic analysis, the scheme with
     * every step started at rest for a static one, and the quasi-static
     * integrator (no inertia; the scheme is not used) for a quasi-static
     * one.
     */
    std::unique_ptr<TimeIntegrator>
    create_time_integrator(std::unique_ptr<TimeIntegrator> scheme,
                           const AnalysisType              analysis);
  } // namespace time
} // namespace ndda

#endif
