// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_constitutive_law_h
#define ndda_physics_constitutive_law_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <ndda/base/plugin_registry.h>
#include <ndda/physics/physics_parameters.h>

#include <memory>

namespace ndda
{
  using dealii::SymmetricTensor;

  /**
   * Interface of a constitutive law (as the material models of step-42):
   * the tangent d sigma / d eps, and the stress update at a quadrature
   * point over a step's strain increment. ndda's stresses are updated
   * incrementally: at the end of a step, every quadrature point's stress
   * is its start stress (turned with the cell's spin, see doc/theory.md)
   * updated by update_stress() with the strain increment of the step's
   * displacement increment d. A cell that d does not move at all (every
   * node's increment exactly zero, as in a fixed block) keeps its
   * stresses: update_stress() is not called for it, so a law must leave a
   * stress unchanged by a zero increment (as rate-independent laws do).
   *
   * The element stiffness is t int B^T C B (thesis 3.24) with C the
   * tangent at each quadrature point. A law whose tangent does not depend
   * on the stress (the default) gives one tangent per material, and
   * element matrices are rebuilt only for cells that moved. A law whose
   * tangent depends on the stress (plasticity, damage, hardening) says so
   * in tangent_depends_on_stress() and gives the tangent at a point's
   * stress in point_tangent(): every cell's element matrices are then
   * rebuilt from the stresses of the step's start at every step (and the
   * system refactorized), as step-42 assembles its tangent from the
   * present state. The step's linear system is then the linearization at
   * the step's start; with an update_stress() that integrates with the
   * same tangent (forward Euler), the internal force at the step's end
   * balances the loads exactly.
   *
   * update_stress(), energy_density() and point_tangent() are called on
   * deal.II's threads (ndda/base/threads.h), for several cells at once:
   * they must change nothing but their @p stress (a law that caches must
   * guard its cache).
   *
   * A law is a plugin (NDDA_REGISTER_PLUGIN with this interface):
   * `set Constitutive law = name` in `subsection Materials` selects it, and
   * its own entries live in `subsection Materials / subsection <name>`.
   * It reads the elastic constants of each material from
   * parameters::Material (Young's modulus, Poisson's ratio), and
   * whatever else it needs from its own entries.
   *
   * @ingroup physics
   */
  class ConstitutiveLaw
  {
  public:
    virtual ~ConstitutiveLaw() = default;

    /** Declare the law's parameters (its subsection is entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the law's parameters (its subsection is entered). */
    virtual void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * The tangent C = d sigma / d eps of @p material, in plane strain or
     * plane stress (@p plane_strain).
     */
    virtual SymmetricTensor<4, 2>
    tangent(const parameters::Material &material,
            const bool                  plane_strain) const = 0;

    /** Whether point_tangent() depends on the stress (default: no). */
    virtual bool
    tangent_depends_on_stress() const
    {
      return false;
    }

    /**
     * The tangent at a quadrature point of @p material whose stress is
     * @p stress. Asked only if tangent_depends_on_stress(); the default
     * is tangent().
     */
    virtual SymmetricTensor<4, 2>
    point_tangent(const parameters::Material  &material,
                  const bool                   plane_strain,
                  const SymmetricTensor<2, 2> &stress) const
    {
      (void)stress;
      return tangent(material, plane_strain);
    }

    /**
     * Update @p stress, the stress at the start of the step (turned with
     * the spin), by the strain increment @p strain_increment of the step.
     * @p tangent is tangent() of @p material. The default is the linear
     * update stress += tangent : strain_increment.
     */
    virtual void
    update_stress(const parameters::Material  &material,
                  const SymmetricTensor<4, 2> &tangent,
                  const SymmetricTensor<2, 2> &strain_increment,
                  SymmetricTensor<2, 2>       &stress) const;

    /**
     * The elastic energy per unit volume that @p stress stores (J/m^3),
     * for the strain energy of the statistics and the energy balance.
     * @p compliance is the inverse of tangent() of @p material (computed
     * once per material, not at every point). The default is that of a
     * linear law: stress : compliance : stress / 2.
     */
    virtual double
    energy_density(const parameters::Material  &material,
                   const SymmetricTensor<4, 2> &compliance,
                   const SymmetricTensor<2, 2> &stress) const;

    static const char *
    plugin_kind()
    {
      return "constitutive law";
    }

    static const char *
    plugin_kinds()
    {
      return "constitutive laws";
    }

    static const char *
    selection_entry()
    {
      return "Materials/Constitutive law";
    }

    /** Keep the built-in laws in every program. */
    static void
    link_builtin_plugins();
  };

  /** The registry of constitutive laws. */
  using ConstitutiveLawRegistry = PluginRegistry<ConstitutiveLaw>;

  /**
   * Isotropic linear elasticity tensor for plane stress or plane strain
   * (thesis eqs. 3.20, 3.21):
   * sigma = lambda tr(eps) I + 2 mu eps, with lambda = E nu / (1 - nu^2)
   * for plane stress and E nu / ((1 + nu)(1 - 2 nu)) for plane strain.
   */
  SymmetricTensor<4, 2>
  isotropic_elasticity_tensor(const double youngs_modulus,
                              const double poissons_ratio,
                              const bool   plane_strain);
} // namespace ndda

#endif
