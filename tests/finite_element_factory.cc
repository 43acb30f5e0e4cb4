// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_element() (physics/finite_element.h): for the elements ndda knows by
// name and for one a program registers with FETools::add_fe_name(), the
// element with what travels with it: the scalar element's name, the dofs of
// the displacement element, the points of the cell, mass and face
// quadratures and the output subdivisions. Then the names it must refuse,
// each with its message.

#include <deal.II/base/exceptions.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_tools.h>
// Debian's libdeal.ii 9.4.1 exports no FETools::add_fe_name<2, 2> and no
// FEFactory<FE>::get(): this program instantiates them.
#include <deal.II/fe/fe_tools.templates.h>

#include <ndda/physics/finite_element.h>

#include <iostream>
#include <sstream>
#include <string>

#include "tests.h"

namespace
{
  /**
   * A vector-valued element on the triangle, registered under a name below
   * so that the refusal of vector elements can be seen: make_element() wants
   * the scalar element.
   */
  class VectorFactory : public dealii::FETools::FEFactoryBase<2>
  {
  public:
    std::unique_ptr<dealii::FiniteElement<2>>
    get(const unsigned int degree) const override
    {
      return std::make_unique<dealii::FESystem<2>>(
        dealii::FE_SimplexP<2>(degree), 2);
    }

    std::unique_ptr<dealii::FiniteElement<2>>
    get(const dealii::Quadrature<1> &) const override
    {
      return nullptr;
    }
  };
} // namespace

int
main()
{
  using namespace dealii;
  // A library user's element: FE_SimplexP under a name of its own.
  FETools::add_fe_name<2, 2>("FE_UserP",
                             new FETools::FEFactory<FE_SimplexP<2>>());
  FETools::add_fe_name<2, 2>("FE_UserVector", new VectorFactory());

  for (const std::string name : {"FE_SimplexP(1)",
                                 "FE_SimplexP(2)",
                                 "FE_SimplexP<2>(2)",
                                 "FE_SimplexP_Bubbles(2)",
                                 "FE_UserP(2)"})
    {
      const ndda::Element element = ndda::make_element(name);
      std::cout << name << ": " << element.scalar->get_name() << ", "
                << element.system->n_dofs_per_cell()
                << " dofs per cell, quadrature points: cell "
                << element.cell_quadrature.size() << ", mass "
                << element.mass_quadrature.size() << ", face "
                << element.face_quadrature.size() << "; output subdivisions "
                << element.n_output_subdivisions << std::endl;
    }

  for (const std::string name : {"FE_Q(1)",
                                 "FE_SimplexDGP(1)",
                                 "FE_Nonsense(1)",
                                 "FE_SimplexP(3)",
                                 "FE_UserVector(1)"})
    {
      try
        {
          ndda::make_element(name);
          std::cout << name << ": FAILED, not refused" << std::endl;
          return 1;
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream message;
          e.print_info(message);
          std::cout << name << ": refused: "
                    << ndda_tests::fold_whitespace(message.str()) << std::endl;
        }
    }
}
