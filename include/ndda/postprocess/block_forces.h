// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_postprocess_block_forces_h
#define ndda_postprocess_block_forces_h

#include <deal.II/base/tensor.h>

namespace ndda
{
  template <int dim>
  class Simulator;

  namespace postprocess
  {
    /**
     * The resultant of the contact forces on the nodes of block @p block
     * at the end of the last step (N; zero before the first step or
     * without contact). A loading plate's load, whatever its kinematics.
     */
    dealii::Tensor<1, 2>
    contact_force_on_block(const Simulator<2> &simulator,
                           const unsigned int  block);
  } // namespace postprocess
} // namespace ndda

#endif
