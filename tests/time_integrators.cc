// SPDX-License-Identifier: GPL-3.0-or-later
//
// The time layer without a simulator (include/ndda/time/):
//
//  - every integrator (DDA, Newmark, static around each, quasi-static) on
//    one degree of freedom, a mass m on a spring k: the coefficients of one
//    step, its right-hand side and the velocity and inertia force it
//    commits, against the formulas of doc/theory.md computed by hand;
//  - a harmonic oscillator over ten periods: Newmark keeps the energy to
//    round-off and its period error is the known (omega dt)^2 / 12; DDA
//    loses energy (numerical damping);
//  - generalized-α on the oscillator: rho_inf = 1 is Newmark step by step;
//    an unresolved mode (omega dt = 1e4) is scaled by rho_inf per step;
//    the error of a resolved one falls as dt^2; its energy is kept to
//    within the scheme's small damping;
//  - generalized-α started from rest under a sudden load: its own start
//    (KinematicState::starting) gains no energy at any rho_inf for modes
//    far above 1/dt, where a start with a(0) overshoots, and keeps second
//    order for a resolved one;
//  - the registry: names, an unknown name, a scheme registered by this
//    program, subsection Control read from a .prm text;
//  - the step controller: attempt sizes, cuts, growth after a cut, the end
//    time, and the messages of its three limits.

#include <deal.II/base/exceptions.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <ndda/time/dda.h>
#include <ndda/time/generalized_alpha.h>
#include <ndda/time/newmark.h>
#include <ndda/time/step_controller.h>
#include <ndda/time/time_integrator.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "tests.h"

using namespace dealii;
using namespace ndda::time;
using ndda_tests::check;
using ndda_tests::message_of;

/** A scheme defined by this program: DDA with another name. */
class Shi : public DDA
{
public:
  static void
  declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Note", "", Patterns::Anything(), "Unused.");
  }
};

NDDA_REGISTER_PLUGIN(TimeIntegrator,
                     Shi,
                     "Shi",
                     "A test scheme: DDA under another name.")

namespace
{
  /** A 1 x 1 matrix with entry @p value. */
  struct Scalar
  {
    explicit Scalar(const double value)
    {
      pattern.reinit(1, 1, 1);
      pattern.add(0, 0);
      pattern.compress();
      matrix.reinit(pattern);
      matrix.set(0, 0, value);
    }
    SparsityPattern      pattern;
    SparseMatrix<double> matrix;
  };

  Vector<double>
  one(const double value)
  {
    Vector<double> v(1);
    v[0] = value;
    return v;
  }

  /**
   * One step of each integrator: m = 2 kg, k = 50 N/m, v0 = 3 m/s,
   * M a0 = -4 N, no external force, dt = 0.1 s.
   */
  void
  test_one_step()
  {
    std::cout << "One step, m = 2, k = 50, v0 = 3, M a0 = -4, dt = 0.1"
              << std::endl;
    const double m = 2, k = 50, dt = 0.1;
    const Scalar mass(m);
    for (const AnalysisType analysis : {AnalysisType::dynamic_analysis,
                                        AnalysisType::static_analysis,
                                        AnalysisType::quasi_static})
      for (const std::string scheme : {"DDA", "Newmark"})
        {
          const auto integrator =
            create_time_integrator(TimeIntegratorRegistry::create(scheme),
                                   analysis);
          KinematicState state{one(3.), one(-4.), {}};
          Vector<double> rhs(1);
          integrator->add_inertia_terms(mass.matrix, state, dt, rhs);
          const double c = integrator->mass_coefficient(dt);
          const double d = rhs[0] / (k + c * m);
          integrator->update(one(d), dt, mass.matrix, one(0.), state);
          const char *name =
            analysis == AnalysisType::dynamic_analysis ? "dynamic" :
            analysis == AnalysisType::static_analysis  ? "static" :
                                                         "quasi-static";
          std::cout << "  " << std::setw(12) << name << ' ' << std::setw(7)
                    << scheme << ": c_M = " << c << ", rhs = " << rhs[0]
                    << ", d = " << d << ", v1 = " << state.velocity[0]
                    << ", M a1 = " << state.inertia_force[0]
                    << ", averages contacts: "
                    << integrator->averages_contact_forces()
                    << ", initial acceleration: "
                    << integrator->needs_initial_acceleration() << std::endl;

          // The formulas of doc/theory.md.
          double c_ref = 0, rhs_ref = 0, v_ref = 0, ma_ref = -4;
          if (analysis != AnalysisType::quasi_static)
            {
              c_ref   = (scheme == "DDA" ? 2. : 4.) / (dt * dt);
              rhs_ref = (scheme == "DDA" ? 2. : 4.) / dt * m * 3. +
                        (scheme == "DDA" ? 0. : -4.);
              v_ref = 2 * d / dt - 3.;
              if (scheme == "Newmark")
                ma_ref = 4. / (dt * dt) * m * (d - dt * 3.) + 4.;
            }
          else
            {
              v_ref  = d / dt;
              ma_ref = 0;
            }
          if (analysis == AnalysisType::static_analysis)
            v_ref = ma_ref = 0;
          check(std::abs(c - c_ref) <= 1e-12 * c_ref &&
                  std::abs(rhs[0] - rhs_ref) <= 1e-12 * std::abs(rhs_ref) &&
                  std::abs(state.velocity[0] - v_ref) <= 1e-12 &&
                  std::abs(state.inertia_force[0] - ma_ref) <= 1e-12,
                std::string(name) + " " + scheme + " step");
          check(integrator->averages_contact_forces() ==
                    (scheme == "Newmark" &&
                     analysis != AnalysisType::quasi_static) &&
                  integrator->needs_initial_acceleration() ==
                    (scheme == "Newmark" &&
                     analysis == AnalysisType::dynamic_analysis),
                std::string(name) + " " + scheme + " flags");
        }
  }

  /**
   * A free oscillator, m = 1, k = (2 pi)^2 (period 1 s), x0 = 1, v0 = 0,
   * dt = 0.02, ten periods: the energy at the end over the energy at the
   * start, and Newmark's phase after ten periods against its known period
   * elongation T (1 + (omega dt)^2 / 12).
   */
  void
  test_oscillator()
  {
    std::cout << "Oscillator, period 1 s, dt = 0.02 s, 10 periods" << std::endl;
    const double m = 1, k = 4 * M_PI * M_PI, dt = 0.02;
    const Scalar mass(m);
    for (const std::string scheme : {"Newmark", "DDA"})
      {
        const auto integrator =
          create_time_integrator(TimeIntegratorRegistry::create(scheme),
                                 AnalysisType::dynamic_analysis);
        double         x = 1;
        KinematicState state{one(0.), one(-k * x), {}};
        const unsigned n_steps    = 500;
        double         x_previous = x, t_last_crossing = 0;
        for (unsigned int n = 1; n <= n_steps; ++n)
          {
            Vector<double> rhs(1);
            rhs[0] = -k * x;
            integrator->add_inertia_terms(mass.matrix, state, dt, rhs);
            const double d =
              rhs[0] / (k + integrator->mass_coefficient(dt) * m);
            integrator->update(one(d), dt, mass.matrix, one(0.), state);
            x += d;
            // Upward zero crossings, by linear interpolation.
            if (x_previous < 0 && x >= 0)
              t_last_crossing = (n - 1 + x_previous / (x_previous - x)) * dt;
            x_previous = x;
          }
        const double energy =
          0.5 * m * state.velocity[0] * state.velocity[0] + 0.5 * k * x * x;
        const double ratio = energy / (0.5 * k);
        std::cout << "  " << std::setw(7) << scheme
                  << ": energy after / before = " << std::setprecision(8)
                  << ratio << std::setprecision(6) << std::endl;
        if (scheme == "Newmark")
          {
            // The tenth upward crossing is at 9.75 periods.
            const double w        = 2 * M_PI;
            const double period   = 1. + (w * dt) * (w * dt) / 12.;
            const double expected = 9.75 * period;
            std::cout << "  Newmark: 10th upward crossing at "
                      << std::setprecision(8) << t_last_crossing
                      << " s, expected " << expected << " s"
                      << std::setprecision(6) << std::endl;
            check(std::abs(ratio - 1.) < 1e-10, "Newmark keeps the energy");
            check(std::abs(t_last_crossing - expected) < 2e-4,
                  "Newmark's period elongation");
          }
        else
          check(ratio < 0.9, "DDA damps the oscillator");
      }
  }

  /** The oscillator m = 1, k = omega^2 from x0 = 1, v0 = 0 (a0 = -k)
   * over @p n_steps steps of @p dt with @p integrator: x and v at the end,
   * and x after every step in @p history if given. */
  std::pair<double, double>
  oscillate(const TimeIntegrator &integrator,
            const double          omega,
            const double          dt,
            const unsigned int    n_steps,
            std::vector<double>  *history = nullptr)
  {
    const double   k = omega * omega;
    const Scalar   mass(1.);
    double         x = 1;
    KinematicState state{one(0.), one(-k * x), {}};
    if (integrator.keeps_acceleration())
      state.acceleration = one(-k * x);
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        Vector<double> rhs(1);
        rhs[0] = -k * x;
        integrator.add_inertia_terms(mass.matrix, state, dt, rhs);
        const double d = rhs[0] / (k + integrator.mass_coefficient(dt));
        integrator.update(one(d), dt, mass.matrix, one(0.), state);
        x += d;
        if (history != nullptr)
          history->push_back(x);
      }
    return {x, state.velocity[0]};
  }



  /** The oscillator m = 1, k = omega^2 at rest at x = 0, under a force
   * f = 1 from t = 0 on, over @p n_steps steps of @p dt: x and v at the
   * end, and the energy v^2 / 2 + k x^2 / 2 - f x after every step, in
   * units of the static solution's strain energy f^2 / (2 k), in
   * @p energies. With @p starting the scheme finds its own start
   * (KinematicState::starting); without, it starts with a0 = a(0) = f. */
  std::pair<double, double>
  load_from_rest(const TimeIntegrator &integrator,
                 const double          omega,
                 const double          dt,
                 const unsigned int    n_steps,
                 const bool            starting,
                 std::vector<double>  *energies = nullptr)
  {
    const double   k = omega * omega, f = 1;
    const Scalar   mass(1.);
    double         x = 0;
    KinematicState state{one(0.), one(f), one(starting ? 0. : f), starting};
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        Vector<double> rhs(1);
        rhs[0] = f - k * x;
        integrator.add_inertia_terms(mass.matrix, state, dt, rhs);
        const double d =
          rhs[0] / (k + integrator.step_mass_coefficient(dt, state));
        integrator.update(one(d), dt, mass.matrix, one(0.), state);
        x += d;
        if (energies != nullptr)
          {
            const double v = state.velocity[0];
            energies->push_back((v * v / 2 + k * x * x / 2 - f * x) /
                                (f * f / (2 * k)));
          }
      }
    return {x, state.velocity[0]};
  }



  void
  test_generalized_alpha_start()
  {
    std::cout << "Generalized-alpha started under a sudden load" << std::endl;
    const double dt = 0.02;
    // The energy of the exact motion stays 0; a scheme that damps the
    // modes it does not resolve takes it towards -1 (the static state).
    for (const double rho : {0., 0.5, 0.8, 1.})
      {
        GeneralizedAlpha alpha;
        alpha.set_spectral_radius(rho);
        std::cout << "  rho_inf = " << rho
                  << ", largest energy over 20 steps at omega dt = 3, 7, 20, "
                     "1000, (started with a(0), own start):";
        double own_largest = -1;
        for (const double omega_dt : {3., 7., 20., 1000.})
          for (const bool starting : {false, true})
            {
              std::vector<double> energies;
              load_from_rest(alpha, omega_dt / dt, dt, 20, starting, &energies);
              const double largest =
                *std::max_element(energies.begin(), energies.end());
              std::cout << (starting ? ", " : " (") << largest
                        << (starting ? ")" : "");
              if (starting)
                own_largest = std::max(own_largest, largest);
              else if (rho == 0. && omega_dt == 20.)
                check(largest > 20.,
                      "started with a(0), rho_inf = 0 overshoots at omega dt "
                      "= 20 by about (omega dt)^2 / 16");
            }
        std::cout << std::endl;
        check(own_largest < 1e-9,
              "generalized-alpha's own start gains no energy");
      }
    // A resolved mode (100 and 200 steps a period) from rest under the
    // load: second order against x = (1 - cos(omega t)) / omega^2, and as
    // accurate as the start with a(0).
    const double     w = 2 * M_PI, t = 10;
    GeneralizedAlpha alpha;
    double           error[2][2];
    for (unsigned int i = 0; i < 2; ++i)
      for (const bool starting : {true, false})
        {
          const double step = dt / (2 << i);
          const auto   end =
            load_from_rest(alpha, w, step, std::lround(t / step), starting);
          error[starting][i] =
            std::hypot(end.first - (1 - std::cos(w * t)) / (w * w),
                       (end.second - std::sin(w * t) / w) / w);
        }
    std::cout << "  rho_inf = 0 from rest, error after 10 periods, dt = 0.01 "
                 "and 0.005: "
              << error[1][0] << ", " << error[1][1] << " (ratio "
              << error[1][0] / error[1][1]
              << "); started with a(0): " << error[0][0] << ", " << error[0][1]
              << std::endl;
    check(error[1][0] / error[1][1] > 3.8 && error[1][0] / error[1][1] < 4.2,
          "generalized-alpha's own start keeps second order");
  }



  void
  test_generalized_alpha()
  {
    std::cout << "Generalized-alpha on the oscillator" << std::endl;
    const double w = 2 * M_PI, dt = 0.02;
    // rho_inf = 1 against Newmark, step by step over ten periods.
    {
      GeneralizedAlpha alpha;
      alpha.set_spectral_radius(1.);
      const auto          newmark = TimeIntegratorRegistry::create("Newmark");
      std::vector<double> xa, xn;
      const auto          end_a   = oscillate(alpha, w, dt, 500, &xa);
      const auto          end_n   = oscillate(*newmark, w, dt, 500, &xn);
      double              largest = 0;
      for (unsigned int n = 0; n < xa.size(); ++n)
        largest = std::max(largest, std::abs(xa[n] - xn[n]));
      std::cout << "  rho_inf = 1 against Newmark, 500 steps: x within "
                   "1e-12 at every step, v within 1e-10 at the end"
                << std::endl;
      check(largest < 1e-12 && std::abs(end_a.second - end_n.second) < 1e-10,
            "generalized-alpha with rho_inf = 1 is Newmark");
    }
    // An unresolved mode (omega dt = 1e6): the spectral radius of the
    // step's amplification matrix, which maps (x, v, a) at the start to
    // (x, v, a) at the end (r = -k x), against rho_inf.
    for (const double rho : {0., 0.5, 0.8, 1.})
      {
        GeneralizedAlpha alpha;
        alpha.set_spectral_radius(rho);
        const double             omega = 1e6 / dt, k = omega * omega;
        const Scalar             mass(1.);
        LAPACKFullMatrix<double> amplification(3, 3);
        for (unsigned int j = 0; j < 3; ++j)
          {
            const double   x = j == 0 ? 1. : 0.;
            KinematicState state{one(j == 1 ? 1. : 0.),
                                 one(-k * x),
                                 one(j == 2 ? 1. : 0.)};
            Vector<double> rhs(1);
            rhs[0] = -k * x;
            alpha.add_inertia_terms(mass.matrix, state, dt, rhs);
            const double d = rhs[0] / (k + alpha.mass_coefficient(dt));
            alpha.update(one(d), dt, mass.matrix, one(0.), state);
            amplification(0, j) = x + d;
            amplification(1, j) = state.velocity[0];
            amplification(2, j) = state.acceleration[0];
          }
        amplification.compute_eigenvalues();
        double radius = 0;
        for (unsigned int i = 0; i < 3; ++i)
          radius = std::max(radius, std::abs(amplification.eigenvalue(i)));
        std::cout << "  rho_inf = " << rho
                  << ", omega dt = 1e6: spectral radius " << radius
                  << std::endl;
        check(std::abs(radius - rho) < 1e-3,
              "generalized-alpha scales an unresolved mode by rho_inf");
      }
    // A resolved mode (50 steps a period): second order, and little
    // damping.
    GeneralizedAlpha alpha;
    alpha.set_spectral_radius(0.8);
    double error[2];
    for (unsigned int i = 0; i < 2; ++i)
      {
        const double step = dt / (1 << i);
        const auto   end  = oscillate(alpha, w, step, 500 << i);
        error[i]          = std::hypot(end.first - 1., end.second / w);
        if (i == 0)
          {
            const double energy =
              end.first * end.first + end.second * end.second / (w * w);
            std::cout << "  rho_inf = 0.8, 50 steps a period, 10 periods: "
                      << "energy after / before " << std::setprecision(8)
                      << energy << std::setprecision(6) << std::endl;
            check(energy < 1. && energy > 0.99,
                  "generalized-alpha keeps a resolved mode's energy to 1 %");
          }
      }
    std::cout << "  error after 10 periods, dt = 0.02 and 0.01: " << error[0]
              << ", " << error[1] << " (ratio " << error[0] / error[1] << ")"
              << std::endl;
    check(error[0] / error[1] > 3.8 && error[0] / error[1] < 4.2,
          "generalized-alpha is second order");
    const std::string bad = message_of([]() {
      GeneralizedAlpha alpha;
      alpha.set_spectral_radius(1.5);
    });
    std::cout << "  rho_inf = 1.5: " << bad << std::endl;
    check(bad.find("Spectral radius at infinity: 1.5") != std::string::npos,
          "message for a spectral radius beyond 1");
  }



  void
  test_registry()
  {
    std::cout << "Registry" << std::endl;
    std::cout << "  names: " << TimeIntegratorRegistry::joined_names()
              << std::endl;
    check(TimeIntegratorRegistry::joined_names() ==
            "DDA|Newmark|Shi|generalized-alpha",
          "registered names");
    const std::string unknown =
      message_of([]() { TimeIntegratorRegistry::create("Verlet"); });
    std::cout << "  unknown name: " << unknown << std::endl;
    check(unknown.find("Control/Time integrator: 'Verlet' is not a time "
                       "integrator. Known time integrators: DDA, Newmark, "
                       "Shi, generalized-alpha.") != std::string::npos,
          "message for an unknown scheme");
    const std::string twice = message_of([]() {
      TimeIntegratorRegistry::add("DDA",
                                  "again",
                                  &DDA::declare_parameters,
                                  nullptr);
    });
    std::cout << "  registered twice: " << twice << std::endl;
    check(twice.find("Two time integrators are registered under the name "
                     "'DDA'") != std::string::npos,
          "message for a name registered twice");

    // A scene selects the program's own scheme by name.
    const auto parameters = ndda_tests::read_parameters(R"(
subsection Control
  set Time integrator = Shi
  set Analysis type   = static
  subsection Shi
    set Note = selected by name
  end
end
subsection Materials
  set Names = rock
  subsection rock
  end
end
subsection Geometry
  set Blocks = b
  subsection b
    set Outer boundary = 0, 0; 1, 0; 1, 1; 0, 1
    set Material = rock
    set Mesh size = 0.5
  end
end
)",
                                                        "shi");
    std::cout << "  scene: Time integrator = "
              << parameters.control.time_integrator_name
              << ", mass coefficient at dt = 0.1: "
              << parameters.control.time_integrator->mass_coefficient(0.1)
              << std::endl;
    check(parameters.control.time_integrator_name == "Shi" &&
            std::abs(parameters.control.time_integrator->mass_coefficient(0.1) -
                     200.) < 1e-10,
          "a scene with the program's scheme");
  }

  /** The limits of the step controller tests: a step of 0.1 s to 0.35 s. */
  StepController::Limits
  step_limits()
  {
    StepController::Limits limits;
    limits.nominal_step              = 0.1;
    limits.end_time                  = 0.35;
    limits.max_cuts                  = 3;
    limits.max_displacement_ratio    = 0.01;
    limits.max_open_close_iterations = 6;
    return limits;
  }



  void
  test_step_controller()
  {
    std::cout << "Step controller" << std::endl;
    const StepController::Limits limits = step_limits();
    StepController               controller(limits);

    double t = 0;
    controller.begin_step(1, t);
    double dt = controller.attempt_size(t);
    dt        = controller.after_failure(AttemptResult::too_large, dt, 1.);
    dt        = controller.after_failure(AttemptResult::penalty_raised, dt, 1.);
    dt        = controller.after_failure(AttemptResult::not_settled, dt, 1.);
    controller.accept(dt);
    t += dt;
    std::cout << "  step 1: " << dt << " s after " << controller.n_cuts()
              << " cuts (" << controller.n_open_close_cuts() << " open-close)"
              << std::endl;
    check(dt == 0.025 && controller.n_cuts() == 2 &&
            controller.n_open_close_cuts() == 1,
          "cuts halve the step, a penalty raise does not");
    std::vector<double> sizes;
    for (unsigned int step = 2; t < limits.end_time * (1 - 1e-12); ++step)
      {
        controller.begin_step(step, t);
        dt = controller.attempt_size(t);
        controller.accept(dt);
        t += dt;
        sizes.push_back(dt);
      }
    std::cout << "  then:";
    for (const double s : sizes)
      std::cout << ' ' << s;
    std::cout << " (total cuts " << controller.n_total_cuts() << ")"
              << std::endl;
    check(sizes.size() == 4 && sizes[0] == 0.05 && sizes[1] == 0.1 &&
            std::abs(sizes[3] - 0.075) < 1e-12 &&
            controller.n_total_cuts() == 2,
          "growth after a cut and the last step to the end time");

    controller.begin_step(7, 0.5);
    const std::string cuts = message_of([&]() {
      double size = 0.1;
      for (;;)
        size = controller.after_failure(AttemptResult::inverted, size, 2.);
    });
    std::cout << "  too many cuts: " << cuts << std::endl;
    check(cuts.find("Step 7 at t = 0.5: a cell still turns inside out") !=
              std::string::npos &&
            cuts.find("after 3 step cuts") != std::string::npos,
          "message of the cut limit");

    controller.begin_step(8, 0.5);
    const std::string raises = message_of([&]() {
      for (;;)
        controller.after_failure(AttemptResult::penalty_raised, 0.1, 0.);
    });
    std::cout << "  too many raises: " << raises << std::endl;
    check(raises.find("the automatic penalty was doubled 30 times") !=
            std::string::npos,
          "message of the raise limit");

    StepController    crawling(limits);
    const std::string crawl = message_of([&]() {
      for (unsigned int step = 1;; ++step)
        {
          crawling.begin_step(step, 0.);
          crawling.accept(1e-5);
          crawling.check_progress(step * 1e-5);
        }
    });
    std::cout << "  crawling: " << crawl << std::endl;
    check(crawl.find("Step 1000 at t = ") != std::string::npos &&
            crawl.find(": 1000 steps in a row were cut") != std::string::npos,
          "message of the crawl guard");

    // Cut after cut to below 1e-6 of the step: the message names the
    // cause, and only a displacement that stays too large is a diverging
    // motion.
    StepController::Limits many_cuts = limits;
    many_cuts.max_cuts               = 100;
    const auto smallest              = [&](const AttemptResult result) {
      StepController controller(many_cuts);
      controller.begin_step(9, 0.5);
      return message_of([&]() {
        double size = 0.1;
        for (;;)
          size = controller.after_failure(result, size, 1e-15);
      });
    };
    const std::string unsettled = smallest(AttemptResult::not_settled);
    const std::string diverging = smallest(AttemptResult::too_large);
    std::cout << "  smallest step, not settled: " << unsettled << std::endl
              << "  smallest step, too large: " << diverging << std::endl;
    check(unsettled.find("raise Contact/Open-close iterations") !=
              std::string::npos &&
            unsettled.find("diverging") == std::string::npos &&
            diverging.find("the motion is diverging (the largest") !=
              std::string::npos,
          "message of the smallest step names its cause");
  }



  void
  test_step_hold()
  {
    const StepController::Limits limits = step_limits();
    // A motion that needs half the step for a while: every growth back
    // to the full step fails (one cut), and the size is held for 1, 2,
    // 4, ... accepted steps before the next try; a growth that holds
    // lets the next cut grow back at once.
    StepController     held(limits);
    std::ostringstream attempts;
    const double       t = 0;
    for (unsigned int step = 1; step <= 16; ++step)
      {
        held.begin_step(step, t);
        double dt = held.attempt_size(t);
        attempts << ' ' << dt;
        if (dt > 0.06 && step < 12)
          dt = held.after_failure(AttemptResult::not_settled, dt, 1.);
        held.accept(dt);
      }
    std::cout << "  held after failed growth:" << attempts.str() << std::endl;
    check(attempts.str() == " 0.1 0.1 0.05 0.1 0.05 0.05 0.1 0.05 0.05 0.05 "
                            "0.05 0.1 0.1 0.1 0.1 0.1",
          "a failed growth holds the size longer");
  }
} // namespace



int
main()
{
  std::cout << std::setprecision(6);
  test_one_step();
  test_oscillator();
  test_generalized_alpha();
  test_generalized_alpha_start();
  test_registry();
  test_step_controller();
  test_step_hold();
  std::cout << "OK" << std::endl;
  return 0;
}
