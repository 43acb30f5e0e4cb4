// SPDX-License-Identifier: GPL-3.0-or-later
//
// The time integrator registry, the defaults of the interface, and the two
// analysis types that are not schemes: static (a scheme whose every step
// starts at rest) and quasi-static (no inertia).

#include <ndda/time/time_integrator.h>

namespace ndda
{
  namespace time
  {
    // The built-in schemes, see NDDA_REGISTER_PLUGIN.
    void
    link_plugin_DDA();
    void
    link_plugin_Newmark();
    void
    link_plugin_GeneralizedAlpha();

    void
    TimeIntegrator::link_builtin_plugins()
    {
      link_plugin_DDA();
      link_plugin_Newmark();
      link_plugin_GeneralizedAlpha();
    }



    void
    TimeIntegrator::declare_parameters(ParameterHandler &)
    {}



    void
    TimeIntegrator::parse_parameters(ParameterHandler &)
    {}



    double
    TimeIntegrator::damping_coefficient(const double dt) const
    {
      return 1. / dt;
    }



    double
    TimeIntegrator::first_step_mass_coefficient(const double dt) const
    {
      return mass_coefficient(dt);
    }



    double
    TimeIntegrator::contact_start_weight() const
    {
      return 0.;
    }



    bool
    TimeIntegrator::needs_initial_acceleration() const
    {
      return false;
    }



    bool
    TimeIntegrator::keeps_acceleration() const
    {
      return false;
    }



    namespace
    {
      /**
       * DDA statics (thesis 3.7): the scheme's step, with the velocity and
       * the acceleration set to zero at its end, so that every step starts
       * at rest. The inertia terms stay: they damp the motion towards
       * equilibrium over the steps.
       */
      class Static : public TimeIntegrator
      {
      public:
        explicit Static(std::unique_ptr<TimeIntegrator> scheme)
          : scheme(std::move(scheme))
        {}

        double
        mass_coefficient(const double dt) const override
        {
          return scheme->mass_coefficient(dt);
        }

        double
        first_step_mass_coefficient(const double dt) const override
        {
          return scheme->first_step_mass_coefficient(dt);
        }

        double
        damping_coefficient(const double dt) const override
        {
          return scheme->damping_coefficient(dt);
        }

        void
        add_inertia_terms(const SparseMatrix<double> &mass,
                          const KinematicState       &start,
                          const double                dt,
                          Vector<double>             &rhs) const override
        {
          scheme->add_inertia_terms(mass, start, dt, rhs);
        }

        double
        contact_start_weight() const override
        {
          return scheme->contact_start_weight();
        }

        void
        update(const Vector<double>       &d,
               const double                dt,
               const SparseMatrix<double> &mass,
               const Vector<double>       &contact_correction,
               KinematicState             &state) const override
        {
          scheme->update(d, dt, mass, contact_correction, state);
          state.velocity      = 0;
          state.inertia_force = 0;
          state.acceleration  = 0;
        }

      private:
        std::unique_ptr<TimeIntegrator> scheme;
      };



      /**
       * No inertia: every step solves equilibrium K d = f_ext - f_int. The
       * velocity is the step's mean velocity d / dt (for output and
       * viscosity only).
       */
      class QuasiStatic : public TimeIntegrator
      {
      public:
        double
        mass_coefficient(const double) const override
        {
          return 0.;
        }

        void
        add_inertia_terms(const SparseMatrix<double> &,
                          const KinematicState &,
                          const double,
                          Vector<double> &) const override
        {}

        void
        update(const Vector<double> &d,
               const double          dt,
               const SparseMatrix<double> &,
               const Vector<double> &,
               KinematicState &state) const override
        {
          state.velocity = d;
          state.velocity /= dt;
          state.inertia_force = 0;
        }
      };
    } // namespace



    std::unique_ptr<TimeIntegrator>
    create_time_integrator(std::unique_ptr<TimeIntegrator> scheme,
                           const AnalysisType              analysis)
    {
      switch (analysis)
        {
          case AnalysisType::static_analysis:
            return std::make_unique<Static>(std::move(scheme));
          case AnalysisType::quasi_static:
            return std::make_unique<QuasiStatic>();
          case AnalysisType::dynamic_analysis:
            break;
        }
      return scheme;
    }
  } // namespace time
} // namespace ndda
