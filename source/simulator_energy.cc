// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Simulator's energy balance (doc/theory.md, "Energy balance"): the
// kinetic energy, the viscous dissipation of a step, the energy gain and
// the numerical energy of the statistics.

#include <ndda/base/threads.h>
#include <ndda/simulator.h>

namespace ndda
{
  template <int dim>
  void
  Simulator<dim>::add_viscous_work(const Vector<double> &d, const double dt)
  {
    // Every built-in scheme solves with the viscous force C d / dt, the
    // step's mean velocity. A scheme that weights the start forces w
    // (TimeIntegrator::contact_start_weight(); Newmark 1/2) carries the
    // last step's viscous force in its start force, so the force that does
    // the work d is C (w v_prev + (1 - w) d / dt), v_prev the last step's
    // mean velocity (none in the first step: the initial acceleration has
    // no viscous force). With Newmark the kinetic energy lost is then
    // exactly this work. C is a multiple of M in each block, the same in
    // every frame.
    const SparseMatrix<double> &damping =
      fem.linear_system.get_damping_matrix();
    const double w = parameters.control.time_integrator->contact_start_weight();
    viscous_work += (1. - w) * matrix_norm_square(damping, d) / dt;
    if (w > 0. && last_mean_velocity.size() == d.size())
      viscous_work += w * matrix_scalar_product(damping, d, last_mean_velocity);
    last_mean_velocity = d;
    last_mean_velocity /= dt;
  }



  template <int dim>
  double
  Simulator<dim>::kinetic_energy() const
  {
    return 0.5 * matrix_norm_square(fem.linear_system.get_mass_matrix(),
                                    kinematics.velocity);
  }



  template <int dim>
  double
  Simulator<dim>::energy_error() const
  {
    return energy_error(kinetic_energy(), strain_energy());
  }



  template <int dim>
  double
  Simulator<dim>::energy_error(const double kinetic, const double strain) const
  {
    const double spring_energy =
      parameters.contact.enabled ? contacts.get_statistics().spring_energy : 0.;
    return kinetic + strain + spring_energy - load_work - prescribed_work -
           initial_kinetic_energy;
  }



  template <int dim>
  double
  Simulator<dim>::numerical_energy(const double kinetic,
                                   const double strain) const
  {
    const double friction = parameters.contact.enabled ?
                              contacts.get_statistics().friction_dissipation :
                              0.;
    return energy_error(kinetic, strain) + friction + viscous_work;
  }



  template void
  Simulator<2>::add_viscous_work(const Vector<double> &, const double);
  template double
  Simulator<2>::kinetic_energy() const;
  template double
  Simulator<2>::energy_error() const;
  template double
  Simulator<2>::energy_error(const double, const double) const;
  template double
  Simulator<2>::numerical_energy(const double, const double) const;
} // namespace ndda
