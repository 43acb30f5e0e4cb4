// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_finite_element_h
#define ndda_physics_finite_element_h

#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>

#include <memory>
#include <string>

namespace ndda
{
  using namespace dealii;

  /**
   * The linear mapping of the triangle, MappingFE(FE_SimplexP(1)), that
   * computes every cell's mapping data afresh.
   *
   * deal.II 9.4's FEValues reuses a cell's Jacobians for the next cell when
   * that cell is a translation of it (CellSimilarity::translation), but only
   * when it runs on one thread (FEValues::check_cell_similarity()). The
   * reused and the recomputed data differ at round-off, so a run on one
   * thread and one on two parted in the seventh digit of an energy after a
   * few contact steps. This mapping passes CellSimilarity::none on and
   * returns it, so that every cell is computed as on two threads, and a
   * run's figures do not depend on the number of threads (doc/design.md).
   *
   * @ingroup physics
   */
  class LinearMapping : public MappingFE<2>
  {
  public:
    LinearMapping();

    std::unique_ptr<Mapping<2>>
    clone() const override;

    /// MappingFE::fill_fe_values() with CellSimilarity::none, whatever
    /// FEValues passed; returns CellSimilarity::none.
    CellSimilarity::Similarity
    fill_fe_values(
      const Triangulation<2>::cell_iterator &cell,
      const CellSimilarity::Similarity       cell_similarity,
      const Quadrature<2>                   &quadrature,
      const Mapping<2>::InternalDataBase    &internal_data,
      dealii::internal::FEValuesImplementation::MappingRelatedData<2>
        &output_data) const override;
  };

  /**
   * A scene's finite element and everything that must travel with it
   * (DESIGN.md decision 2): the displacement element, its quadratures, the
   * mapping and the output subdivisions. Made by make_element() only, so
   * that a new element needs nothing but its name.
   *
   * @ingroup physics
   */
  struct Element
  {
    /// The scalar element the scene names, e.g. FE_SimplexP<2>(1).
    std::unique_ptr<const FiniteElement<2>> scalar;
    /// The displacement element FESystem(scalar, 2); its owner may take it.
    std::unique_ptr<FESystem<2>> system;
    /// Stiffness, strain and stress: QGaussSimplex(degree), one point for
    /// P1 (whose strain is constant); the cell stresses live at its points.
    Quadrature<2> cell_quadrature;
    /// Consistent mass: QGaussSimplex(degree + 1).
    Quadrature<2> mass_quadrature;
    /// Line loads (pressure, traction) on cell faces:
    /// QGaussSimplex<1>(degree + 1).
    Quadrature<1> face_quadrature;
    /// The mapping, linear_mapping() for every element (see there).
    LinearMapping mapping;
    /// DataOut::build_patches() subdivisions: the element's degree, at most
    /// 2 (deal.II 9.4.1 writes triangles as linear or quadratic VTK cells
    /// only). HDF5/XDMF output works only with 1.
    unsigned int n_output_subdivisions;
  };

  /**
   * The element named @p name (the entry Control/Finite element) and what
   * travels with it; "degree" above is the element's FiniteElement::degree,
   * the degree of its polynomial space (3 for FE_SimplexP_Bubbles(2)).
   *
   * Names: FE_SimplexP(k) and FE_SimplexP_Bubbles(k) with k = 1 or 2 (what
   * deal.II 9.4.1 implements; FE_SimplexP(3) crashes in its constructor),
   * also written as get_name() prints them (FE_SimplexP<2>(2)), and
   * FE_SimplexDGP(k), which is then refused. deal.II 9.4.1's
   * FETools::get_fe_by_name() knows none of the simplex elements; every
   * other name goes to it, so that an element registered with
   * FETools::add_fe_name<2, 2>(name, factory) is found by its name too.
   * (Debian's libdeal.ii 9.4.1 exports no add_fe_name: a program that
   * registers an element includes <deal.II/fe/fe_tools.templates.h>; see
   * tests/finite_element_factory.cc.)
   *
   * Refused with an ExcMessage that names Control/Finite element, the value
   * and the fix: an unknown name, an element not on the triangle, one with
   * more than one vector component (ndda builds the vector element itself),
   * one without exactly one dof on each vertex (contacts and constraints
   * act on vertex dofs: discontinuous elements cannot be used), one without
   * support points, and one whose mass quadrature deal.II's QGaussSimplex
   * does not have (degree above 3).
   *
   * @param name The element's name, e.g. FE_SimplexP(2).
   * @ingroup physics
   */
  Element
  make_element(const std::string &name);

  /**
   * The mapping of every element make_element() accepts: the linear
   * mapping of the triangle, a LinearMapping, whatever the
   * degree. ndda moves the mesh by its vertices, so cells stay
   * straight-sided triangles. It depends on the reference cell only, so a
   * Simulator holds it from its construction on, before it knows its
   * element.
   *
   * @ingroup physics
   */
  LinearMapping
  linear_mapping();
} // namespace ndda

#endif
