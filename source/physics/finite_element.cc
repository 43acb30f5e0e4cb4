// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_simplex_p_bubbles.h>
#include <deal.II/fe/fe_tools.h>

#include <ndda/physics/finite_element.h>

#include <algorithm>
#include <regex>

namespace ndda
{
  namespace
  {
    /**
     * Refuse the element named @p name unless @p condition: the message
     * names the entry and the value, says what is wrong (@p problem) and
     * what to give instead (@p wanted).
     */
    void
    require(const bool         condition,
            const std::string &name,
            const std::string &problem,
            const std::string &wanted)
    {
      AssertThrow(condition,
                  ExcMessage("Control/Finite element: '" + name + "' " +
                             problem + ". Give " + wanted +
                             ", such as 'FE_SimplexP(1)' or "
                             "'FE_SimplexP(2)'."));
    }

    /**
     * The simplex elements deal.II 9.4.1 has, which its get_fe_by_name()
     * does not know; nullptr for any other name. Degrees are checked before
     * construction: FE_SimplexP(3) crashes in deal.II 9.4.1 (Release)
     * instead of throwing.
     */
    std::unique_ptr<const FiniteElement<2>>
    make_simplex_element(const std::string &name)
    {
      static const std::regex pattern(
        R"(\s*(FE_SimplexP|FE_SimplexP_Bubbles|FE_SimplexDGP)(<2>)?\(\s*(\d+)\s*\)\s*)");
      std::smatch match;
      if (!std::regex_match(name, match, pattern))
        return nullptr;
      const std::string  family = match[1];
      const unsigned int degree = std::stoul(match[3]);
      require(degree == 1 || degree == 2,
              name,
              "has degree " + std::to_string(degree) +
                ", but deal.II 9.4.1 implements " + family +
                " for degree 1 and 2 only",
              "degree 1 or 2");
      if (family == "FE_SimplexP")
        return std::make_unique<FE_SimplexP<2>>(degree);
      if (family == "FE_SimplexP_Bubbles")
        return std::make_unique<FE_SimplexP_Bubbles<2>>(degree);
      return std::make_unique<FE_SimplexDGP<2>>(degree);
    }

    /** Any other element, from deal.II's list (and what was added to it). */
    std::unique_ptr<const FiniteElement<2>>
    make_registered_element(const std::string &name)
    {
      std::unique_ptr<const FiniteElement<2>> fe;
      try
        {
          fe = FETools::get_fe_by_name<2, 2>(name);
        }
      catch (const std::exception &)
        {}
      require(fe != nullptr,
              name,
              "is not an element ndda knows (FE_SimplexP(k), "
              "FE_SimplexP_Bubbles(k), k = 1 or 2), nor one that deal.II's "
              "FETools::get_fe_by_name() knows or a program registered with "
              "FETools::add_fe_name()",
              "one of these");
      return fe;
    }

    /** Refuse an element ndda cannot compute with. */
    void
    check(const FiniteElement<2> &fe, const std::string &name)
    {
      require(fe.reference_cell() == ReferenceCells::Triangle,
              name,
              "is an element on the " + fe.reference_cell().to_string() +
                ", but ndda's cells are triangles",
              "a triangle (simplex) element");
      require(fe.n_components() == 1,
              name,
              "has " + std::to_string(fe.n_components()) +
                " vector components, but ndda builds the displacement "
                "element FESystem(element, 2) itself",
              "the scalar element");
      require(fe.n_dofs_per_vertex() == 1,
              name,
              "has " + std::to_string(fe.n_dofs_per_vertex()) +
                " dofs on each vertex, but ndda's contacts and constraints "
                "act on the vertex dofs and need exactly one per vertex "
                "(discontinuous elements cannot be used)",
              "a continuous element");
      require(fe.has_support_points(),
              name,
              "has no support points, but ndda places initial velocities "
              "and constraints at them",
              "a nodal element");
      // QGaussSimplex<2> has 1 to 4 points per direction in deal.II 9.4.
      require(fe.degree + 1 <= 4,
              name,
              "has degree " + std::to_string(fe.degree) +
                ", but its consistent mass needs QGaussSimplex(" +
                std::to_string(fe.degree + 1) +
                "), and deal.II 9.4 has it up to 4",
              "an element of degree 3 or less");
    }
  } // namespace



  Element
  make_element(const std::string &name)
  {
    std::unique_ptr<const FiniteElement<2>> scalar = make_simplex_element(name);
    if (!scalar)
      scalar = make_registered_element(name);
    check(*scalar, name);

    // Strain, stress and stiffness need degree 2 (p - 1) (one point for P1,
    // whose strain is constant); the consistent mass needs degree 2 p; on a
    // face, a shape function times a load of degree p + 1 needs 2 p + 1.
    // Output: deal.II 9.4.1 writes a triangle patch as a linear or a
    // quadratic VTK cell only (3 subdivisions fail in write_vtu).
    const unsigned int degree = scalar->degree;
    auto               system = std::make_unique<FESystem<2>>(*scalar, 2);
    return Element{std::move(scalar),
                   std::move(system),
                   QGaussSimplex<2>(degree),
                   QGaussSimplex<2>(degree + 1),
                   QGaussSimplex<1>(degree + 1),
                   linear_mapping(),
                   std::min(degree, 2u)};
  }



  LinearMapping::LinearMapping()
    : MappingFE<2>(FE_SimplexP<2>(1))
  {}



  std::unique_ptr<Mapping<2>>
  LinearMapping::clone() const
  {
    return std::make_unique<LinearMapping>(*this);
  }



  CellSimilarity::Similarity
  LinearMapping::fill_fe_values(
    const Triangulation<2>::cell_iterator &cell,
    const CellSimilarity::Similarity,
    const Quadrature<2>                &quadrature,
    const Mapping<2>::InternalDataBase &internal_data,
    dealii::internal::FEValuesImplementation::MappingRelatedData<2>
      &output_data) const
  {
    MappingFE<2>::fill_fe_values(
      cell, CellSimilarity::none, quadrature, internal_data, output_data);
    return CellSimilarity::none;
  }



  LinearMapping
  linear_mapping()
  {
    return LinearMapping();
  }
} // namespace ndda
