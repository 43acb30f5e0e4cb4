// SPDX-License-Identifier: GPL-3.0-or-later
//
// The block kinematics registry and the built-in models: meshed, affine
// (Shi's DDA block) and rigid.

#include <ndda/kinematics/automatic_kinematics.h>
#include <ndda/kinematics/block_kinematics.h>

namespace ndda
{
  namespace kinematics
  {
    void
    link_plugin_Meshed();
    void
    link_plugin_Affine();
    void
    link_plugin_Rigid();

    void
    BlockKinematics::link_builtin_plugins()
    {
      link_plugin_Meshed();
      link_plugin_Affine();
      link_plugin_Rigid();
    }



    void
    check_name(const std::string &name, const std::string &entry)
    {
      const auto &known = BlockKinematicsRegistry::registered();
      AssertThrow(known.count(name) == 1 || name == automatic_name,
                  dealii::ExcMessage(
                    entry + ": '" + name +
                    "' is not a block kinematics model. Known models: " +
                    BlockKinematicsRegistry::joined_names(", ") + ", and " +
                    automatic_name + "."));
    }



    void
    BlockKinematics::declare_parameters(dealii::ParameterHandler &)
    {}



    void
    BlockKinematics::parse_parameters(dealii::ParameterHandler &)
    {}



    void
    Affine::basis(const dealii::Tensor<1, 2> &r,
                  double                     *row_x,
                  double                     *row_y) const
    {
      // q = (a_x, a_y, G_xx, G_xy, G_yx, G_yy): u = a + G r.
      const double x[6] = {1, 0, r[0], r[1], 0, 0};
      const double y[6] = {0, 1, 0, 0, r[0], r[1]};
      std::copy(x, x + 6, row_x);
      std::copy(y, y + 6, row_y);
    }



    void
    Rigid::basis(const dealii::Tensor<1, 2> &r,
                 double                     *row_x,
                 double                     *row_y) const
    {
      // q = (a_x, a_y, theta): u = a + theta (-r_y, r_x).
      const double x[3] = {1, 0, -r[1]};
      const double y[3] = {0, 1, r[0]};
      std::copy(x, x + 3, row_x);
      std::copy(y, y + 3, row_y);
    }



    NDDA_REGISTER_BLOCK_KINEMATICS(
      Meshed,
      "meshed",
      "The block is its finite element mesh: every node moves on its own "
      "(2 unknowns per node), with the element of Control/Finite element, "
      "co-rotational (small strain in the block's frame, exact finite "
      "rotation). Needed where stresses vary over a block and where it "
      "may crack.")

    NDDA_REGISTER_BLOCK_KINEMATICS(
      Affine,
      "affine",
      "Shi's DDA block: 6 unknowns (translation, rotation and a constant "
      "strain). Every node of the block follows one affine field; the "
      "block's stiffness and mass are those of its mesh for that field "
      "(exactly the DDA block matrices), its stress is constant, its "
      "rotation exact. The block does not crack.")

    NDDA_REGISTER_BLOCK_KINEMATICS(
      Rigid,
      "rigid",
      "A rigid block: 3 unknowns (translation and rotation, exact finite "
      "rotation). It does not deform: its strain and stress stay "
      "zero (an initial stress stays as given), and it does not crack. "
      "For loading plates, bases and blocks whose deformation does not "
      "matter.")
  } // namespace kinematics
} // namespace ndda
