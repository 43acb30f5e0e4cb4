// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_rotation_h
#define ndda_physics_rotation_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <utility>

namespace ndda
{
  /**
   * Finite rotations in the plane: the polar decomposition F = R U of a
   * deformation gradient, and tensors turned by a rotation. ndda's
   * kinematics take the rotation out of every step exactly with these
   * (doc/theory.md, "Finite rotation").
   *
   * @ingroup physics
   */
  namespace rotation
  {
    using dealii::SymmetricTensor;
    using dealii::Tensor;

    /**
     * The angle of R in the polar decomposition F = R U of a 2x2 @p F
     * with positive determinant: U = R^T F symmetric makes
     * tan(angle) = (F10 - F01) / (F00 + F11).
     */
    inline double
    polar_angle(const Tensor<2, 2> &F)
    {
      return std::atan2(F[1][0] - F[0][1], F[0][0] + F[1][1]);
    }

    /**
     * cos(angle) - 1 and sin(angle), without the cancellation of
     * cos(angle) - 1 for small angles.
     */
    inline std::pair<double, double>
    cos_minus_one_sin(const double angle)
    {
      const double h = std::sin(0.5 * angle);
      return {-2. * h * h, std::sin(angle)};
    }

    /** The rotation matrix of @p angle from cos - 1 and sin. */
    inline Tensor<2, 2>
    matrix(const double cos_minus_one, const double sin)
    {
      Tensor<2, 2> R;
      R[0][0] = R[1][1] = 1. + cos_minus_one;
      R[0][1]           = -sin;
      R[1][0]           = sin;
      return R;
    }

    /** R s R^T for the rotation R of cos @p c and sin @p s. */
    inline SymmetricTensor<2, 2>
    turn(const SymmetricTensor<2, 2> &t, const double c, const double s)
    {
      SymmetricTensor<2, 2> r;
      const double          xx = t[0][0], yy = t[1][1], xy = t[0][1];
      r[0][0] = c * c * xx - 2 * c * s * xy + s * s * yy;
      r[1][1] = s * s * xx + 2 * c * s * xy + c * c * yy;
      r[0][1] = c * s * (xx - yy) + (c * c - s * s) * xy;
      return r;
    }

    /** A step's strain and the rotation of its polar split (step_strain()). */
    struct StepStrain
    {
      /// V - I, in the step's end frame.
      SymmetricTensor<2, 2> strain;
      /// cos(angle) - 1 and sin(angle) of R.
      double cos_minus_one = 0, sin = 0;
    };

    /**
     * The strain of the step whose displacement gradient on the step's
     * start geometry is @p G, and its rotation: F = I + G = V R, returned
     * as V - I and R's cosine less one and sine. V - I is the strain in the
     * step's end frame (the left stretch less the identity); a rigid
     * motion of any size has V = I, so it strains nothing.
     *
     * R's angle has tan = b / a, a = F00 + F11, b = F10 - F01
     * (polar_angle()); its cosine and sine are a / r and b / r,
     * r = sqrt(a^2 + b^2), computed without a trigonometric function (this
     * runs at every quadrature point in every step), and
     * cos - 1 = (a - r) / r = -b^2 / (r (r + a)) without cancellation for
     * the small turns of a step (a > 0).
     */
    inline StepStrain
    step_strain(const Tensor<2, 2> &G)
    {
      const double a = 2. + G[0][0] + G[1][1];
      const double b = G[1][0] - G[0][1];
      const double r = std::sqrt(a * a + b * b);
      StepStrain   result;
      result.sin           = b / r;
      result.cos_minus_one = a > 0. ? -b * b / (r * (r + a)) : (a - r) / r;
      // V - I = F R^T - I = G R^T + (R^T - I), whose symmetric part is
      // sym(G R^T) + (cos - 1) I: no cancellation for small strains.
      result.strain = dealii::symmetrize(
        G * dealii::transpose(matrix(result.cos_minus_one, result.sin)));
      result.strain[0][0] += result.cos_minus_one;
      result.strain[1][1] += result.cos_minus_one;
      return result;
    }
  } // namespace rotation
} // namespace ndda

#endif
