// SPDX-License-Identifier: GPL-3.0-or-later
//
// The constitutive law registry, the defaults of the interface (the linear
// update), and the built-in law: isotropic linear elasticity.

#include <ndda/physics/constitutive_law.h>

namespace ndda
{
  void
  link_plugin_LinearElasticity();

  void
  ConstitutiveLaw::link_builtin_plugins()
  {
    link_plugin_LinearElasticity();
  }



  void
  ConstitutiveLaw::declare_parameters(dealii::ParameterHandler &)
  {}



  void
  ConstitutiveLaw::parse_parameters(dealii::ParameterHandler &)
  {}



  void
  ConstitutiveLaw::update_stress(const parameters::Material &,
                                 const SymmetricTensor<4, 2> &tangent,
                                 const SymmetricTensor<2, 2> &strain_increment,
                                 SymmetricTensor<2, 2>       &stress) const
  {
    stress += tangent * strain_increment;
  }



  double
  ConstitutiveLaw::energy_density(const parameters::Material &,
                                  const SymmetricTensor<4, 2> &compliance,
                                  const SymmetricTensor<2, 2> &stress) const
  {
    return 0.5 * (stress * (compliance * stress));
  }



  SymmetricTensor<4, 2>
  isotropic_elasticity_tensor(const double E,
                              const double nu,
                              const bool   plane_strain)
  {
    const double mu     = E / (2. * (1. + nu));
    const double lambda = plane_strain ? E * nu / ((1. + nu) * (1. - 2. * nu)) :
                                         E * nu / (1. - nu * nu);
    SymmetricTensor<4, 2> C;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int l = 0; l < 2; ++l)
            C[i][j][k][l] = (i == j && k == l ? lambda : 0.) +
                            (i == k && j == l ? mu : 0.) +
                            (i == l && j == k ? mu : 0.);
    return C;
  }



  namespace
  {
    /**
     * Isotropic linear elasticity in plane stress or plane strain (thesis
     * 3.20, 3.21), from each material's Young's modulus and Poisson's
     * ratio.
     */
    class LinearElasticity : public ConstitutiveLaw
    {
    public:
      SymmetricTensor<4, 2>
      tangent(const parameters::Material &material,
              const bool                  plane_strain) const override
      {
        return isotropic_elasticity_tensor(material.youngs_modulus,
                                           material.poissons_ratio,
                                           plane_strain);
      }
    };
  } // namespace

  NDDA_REGISTER_PLUGIN(ConstitutiveLaw,
                       LinearElasticity,
                       "linear elasticity",
                       "Isotropic linear elasticity in plane stress or plane "
                       "strain (Materials/Plane condition) from each "
                       "material's Young's modulus and Poisson's ratio "
                       "(thesis 3.20, 3.21); stresses are updated "
                       "incrementally, sigma += C eps(d), after the start "
                       "stress is turned with the cell's spin.")
} // namespace ndda
