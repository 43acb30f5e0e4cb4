// SPDX-License-Identifier: GPL-3.0-or-later
//
// The contact law "penalty Coulomb" (doc/contact.md, "Kernels", "The
// open-close iteration", "Bonded joints", "Contact laws") on one vertex
// against one edge of a P1 triangle, without a Simulator, against values
// computed by hand:
//
//  - the springs of a locked and of a sliding contact: stiffness entries
//    and forces at d = 0, and the stiffness scale of the Newmark
//    integrator;
//  - the springs against the energy: the forces are minus its gradient,
//    the stiffness of a locked contact its Hessian (finite differences);
//  - the classification of trial gaps and slips: open, closed within the
//    state tolerance, locked, sliding either way at the Coulomb limit, a
//    sliding contact that keeps sliding or reverses, frictionless
//    contacts; the anchor of a contact that locks after sliding;
//  - the bond check: tension and shear limits, Mohr-Coulomb with the
//    normal force, and which joint strengths make a law bond;
//  - the energy of a locked and of a sliding contact;
//  - the registry: the built-in names, an unknown name, a law registered by
//    this program, its parameters read from its own subsection.
//
// The edge runs from a = (0, 0) to b = (1, 0) (body above, outward normal
// (0, -1)); the vertex P projects at ratio r = 1/4. k_n = 1000 N/m,
// shear ratio 0.4 (k_s = 400 N/m), mu = 0.5.

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/contact/contact_law.h>

#include <cmath>
#include <iostream>

#include "tests.h"

using namespace dealii;
using namespace ndda::contact;
using ndda_tests::check;
using ndda_tests::check_value;

/** A law defined by this program: no springs at all. */
class NoContact : public ContactLaw
{
public:
  static void
  declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Note", "none", Patterns::Anything(), "Unused.");
  }

  void
  parse_parameters(ParameterHandler &prm) override
  {
    note = prm.get("Note");
  }

  void
  add_springs(const Option &,
              const ContactState &,
              const double,
              const ContactSettings &,
              FullMatrix<double> *,
              Vector<double> &) const override
  {}

  State
  classify(const Option &,
           const ContactState &,
           const Trial &,
           const ContactSettings &,
           int &sign) const override
  {
    sign = 0;
    return State::open;
  }

  double
  energy(const Option &,
         const ContactState &,
         const Trial &,
         const ContactSettings &) const override
  {
    return 0.;
  }

  std::string note;
};

NDDA_REGISTER_CONTACT_LAW(NoContact,
                          "no contact",
                          "A test law: contacts never close.")



namespace
{
  /** Print a state and check it against the expected one. */
  void
  check_state(const std::string &what,
              const State        state,
              const int          sign,
              const State        expected,
              const int          expected_sign)
  {
    const char *names[] = {"open", "locked", "sliding", "vertex spring"};
    std::cout << "  " << what << ": " << names[static_cast<int>(state)];
    if (state == State::sliding)
      std::cout << " " << (sign > 0 ? "+" : sign < 0 ? "-" : "0");
    std::cout << std::endl;
    check(state == expected && sign == expected_sign, what);
  }

  /**
   * The option of P against the edge a-b of the triangle (a, b, c), P1,
   * as ContactHandler makes it: P's dofs 0 and 1, the triangle's dofs 2-7
   * (x and y of a, b, c), gap operators e_n and e_t.
   */
  Option
  vertex_on_edge(const double ratio, const double gap)
  {
    Option o;
    o.vertex  = 0;
    o.edge    = 0;
    o.tangent = Tensor<1, 2>({1., 0.});
    o.normal  = Tensor<1, 2>({0., -1.});
    o.length  = 1.;
    o.ratio   = ratio;
    o.gap     = gap;
    o.dofs    = {0, 1, 2, 3, 4, 5, 6, 7};
    // Shape functions of a, b, c at the contact point.
    const double N[3] = {1. - ratio, ratio, 0.};
    o.wn.resize(8);
    o.wt.resize(8);
    for (unsigned int c = 0; c < 2; ++c)
      {
        o.wn[c] = o.normal[c];
        o.wt[c] = o.tangent[c];
        for (unsigned int i = 0; i < 3; ++i)
          {
            o.wn[2 + 2 * i + c] = -N[i] * o.normal[c];
            o.wt[2 + 2 * i + c] = -N[i] * o.tangent[c];
          }
      }
    return o;
  }

  ContactSettings
  make_settings()
  {
    ContactSettings settings;
    settings.normal_stiffness = 1000.;
    settings.shear_ratio      = 0.4;
    settings.state_tolerance  = 1e-9;
    return settings;
  }

  ContactState
  make_state(const State  state,
             const double anchor,
             const int    sign,
             const double friction = 0.5)
  {
    ContactState s;
    s.state    = state;
    s.anchor   = anchor;
    s.sign     = sign;
    s.friction = friction;
    return s;
  }



  void
  springs(const ContactLaw &law)
  {
    const ContactSettings settings = make_settings();
    // P 1 mm inside the body (gap -1e-3), 5 cm along the edge from its
    // anchor (ratio 0.25, anchor 0.2).
    const Option o = vertex_on_edge(0.25, -1e-3);

    std::cout << "locked: penetration 1 mm, shear displacement 5 cm"
              << std::endl;
    FullMatrix<double> k(8, 8);
    Vector<double>     f(8);
    law.add_springs(o, make_state(State::locked, 0.2, 0), 1., settings, &k, f);
    // k_n e_n e_n^T + k_s e_t e_t^T; -k_n g0 e_n - k_s s0 e_t.
    check_value("K(Px, Px) = k_s", k(0, 0), 400.);
    check_value("K(Py, Py) = k_n", k(1, 1), 1000.);
    check_value("K(Px, Py)", k(0, 1), 0.);
    check_value("K(Px, ax) = -k_s (1 - r)", k(0, 2), -300.);
    check_value("K(Py, by) = -k_n r", k(1, 5), -250.);
    check_value("K(ay, by) = k_n (1 - r) r", k(3, 5), 187.5);
    check_value("K(cx, cx): c takes no part", k(6, 6), 0.);
    check_value("F(Px) = -k_s s0", f[0], -20.);
    check_value("F(Py) = -k_n |g0| (pushed out)", f[1], -1.);
    check_value("F(ax) = k_s s0 (1 - r)", f[2], 15.);
    check_value("F(ay)", f[3], 0.75);
    check_value("F(by)", f[5], 0.25);
    double sum_x = 0, sum_y = 0;
    for (unsigned int i = 0; i < 8; i += 2)
      sum_x += f[i], sum_y += f[i + 1];
    check(std::abs(sum_x) < 1e-12 && std::abs(sum_y) < 1e-12,
          "the forces are in balance");
    std::cout << "  the forces on P and on the triangle are in balance"
              << std::endl;

    std::cout << "sliding +x, mu = 0.5" << std::endl;
    k = 0;
    f = 0;
    law.add_springs(
      o, make_state(State::sliding, 0.2, +1), 1., settings, &k, f);
    // k_n e_n e_n^T - sign mu k_n e_t e_n^T; -k_n g0 e_n + sign mu k_n g0 e_t.
    check_value("K(Px, Px): no shear spring", k(0, 0), 0.);
    check_value("K(Px, Py) = sign mu k_n", k(0, 1), 500.);
    check_value("K(Py, Px) = 0 (non-symmetric)", k(1, 0), 0.);
    check_value("F(Px) = -sign mu N", f[0], -0.5);
    check_value("F(Py)", f[1], -1.);

    std::cout << "without friction or sliding direction" << std::endl;
    f = 0;
    law.add_springs(
      o, make_state(State::sliding, 0.2, 0, 0.), 1., settings, nullptr, f);
    check_value("F(Px)", f[0], 0.);

    std::cout << "scale 0.5 (Newmark)" << std::endl;
    k = 0;
    f = 0;
    law.add_springs(o, make_state(State::locked, 0.2, 0), 0.5, settings, &k, f);
    check_value("K(Py, Py)", k(1, 1), 500.);
    check_value("F(Px)", f[0], -10.);
  }



  /**
   * The springs of a locked contact against its energy: F = -grad E and
   * K = grad grad E at d = 0, by central differences on d.
   */
  void
  springs_and_energy(const ContactLaw &law)
  {
    const ContactSettings settings = make_settings();
    const Option          o        = vertex_on_edge(0.25, -1e-3);
    const ContactState    locked   = make_state(State::locked, 0.2, 0);
    FullMatrix<double>    k(8, 8);
    Vector<double>        f(8);
    law.add_springs(o, locked, 1., settings, &k, f);

    const double h      = 1e-4;
    const auto   energy = [&](const Vector<double> &d) {
      return law.energy(o, locked, Trial(o, d), settings);
    };
    double force_error = 0, stiffness_error = 0;
    for (unsigned int i = 0; i < 8; ++i)
      {
        Vector<double> plus(8), minus(8);
        plus[i]               = h;
        minus[i]              = -h;
        const double gradient = (energy(plus) - energy(minus)) / (2 * h);
        force_error = std::max(force_error, std::abs(f[i] + gradient));
        for (unsigned int j = 0; j < 8; ++j)
          {
            Vector<double> pp(8), pm(8), mp(8), mm(8);
            pp[i] += h, pp[j] += h;
            pm[i] += h, pm[j] -= h;
            mp[i] -= h, mp[j] += h;
            mm[i] -= h, mm[j] -= h;
            const double hessian =
              (energy(pp) - energy(pm) - energy(mp) + energy(mm)) / (4 * h * h);
            stiffness_error =
              std::max(stiffness_error, std::abs(k(i, j) - hessian));
          }
      }
    std::cout << "locked springs against the energy (central differences)"
              << std::endl;
    std::cout << "  F = -grad E: " << (force_error < 1e-6 ? "yes" : "no")
              << std::endl;
    std::cout << "  K = grad grad E: "
              << (stiffness_error < 1e-3 ? "yes" : "no") << std::endl;
    check(force_error < 1e-6, "F = -grad E");
    check(stiffness_error < 1e-3, "K = grad grad E");
  }



  void
  classification(const ContactLaw &law)
  {
    const ContactSettings settings = make_settings();
    const Option          o        = vertex_on_edge(0.25, 0.);
    // Classify contact @p s after the trial (gap, increment).
    const auto expect = [&](const std::string  &what,
                            const ContactState &s,
                            const double        gap,
                            const double        increment,
                            const State         expected,
                            const int           expected_sign) {
      int         sign = 7;
      const State state =
        law.classify(o, s, Trial(gap, increment), settings, sign);
      check_state(what, state, sign, expected, expected_sign);
    };

    std::cout << "an open contact" << std::endl;
    const ContactState open = make_state(State::open, 0.25, 0);
    expect("gap 1 mm", open, 1e-3, 0., State::open, 0);
    expect("penetration 0.5e-9 m, within the state tolerance",
           open,
           -0.5e-9,
           0.,
           State::open,
           0);
    expect("penetration 1 mm, no slip", open, -1e-3, 0., State::locked, 0);

    // Coulomb limit mu k_n |g| = 0.5 N at 1 mm; k_s s reaches it at
    // s = 1.25 mm.
    std::cout << "a locked contact, penetration 1 mm, Coulomb limit 0.5 N"
              << std::endl;
    const ContactState locked = make_state(State::locked, 0.25, 0);
    expect("gap 1 mm", locked, 1e-3, 0., State::open, 0);
    expect("gap 0.5e-9 m: touching without force, keeps its state",
           locked,
           0.5e-9,
           0.,
           State::locked,
           0);
    expect("slip 0.4 mm", locked, -1e-3, 4e-4, State::locked, 0);
    const double at_limit = 0.5 / 400.;
    expect("slip at 0.999999 of the limit",
           locked,
           -1e-3,
           0.999999 * at_limit,
           State::locked,
           0);
    expect("slip at 1.000001 of the limit",
           locked,
           -1e-3,
           1.000001 * at_limit,
           State::sliding,
           +1);
    expect("slip -2 mm", locked, -1e-3, -2e-3, State::sliding, -1);
    expect("anchor 1.5 mm behind, no slip",
           make_state(State::locked, 0.2485, 0),
           -1e-3,
           0.,
           State::sliding,
           +1);

    std::cout << "a contact sliding +x" << std::endl;
    const ContactState sliding = make_state(State::sliding, 0.25, +1);
    expect("moving on 1 mm", sliding, -1e-3, 1e-3, State::sliding, +1);
    expect("moving back 0.5e-9 m, within the state tolerance",
           sliding,
           -1e-3,
           -0.5e-9,
           State::sliding,
           +1);
    expect("moving back 1 mm: locks", sliding, -1e-3, -1e-3, State::locked, 0);
    const double anchor =
      law.anchor_on_locking(o, sliding, Trial(-1e-3, -1e-3), settings);
    // k_s s0 = sign mu k_n |g|: s0 = 1.25 mm behind the vertex.
    check_value("its anchor: ratio", anchor, 0.25 - 0.00125);
    check_value("its shear spring's force k_s s0 = mu k_n |g|",
                400. * (0.25 - anchor),
                0.5);
    check_value("anchor of a contact that locks from open",
                law.anchor_on_locking(o, open, Trial(-1e-3, 0.), settings),
                0.25);

    std::cout << "frictionless" << std::endl;
    expect("penetration 1 mm, no slip",
           make_state(State::locked, 0.25, 0, 0.),
           -1e-3,
           0.,
           State::sliding,
           0);
  }



  void
  bonds(const ContactLaw &law)
  {
    ContactSettings settings = make_settings();
    std::cout << "bonds" << std::endl;
    check(!law.bonds_initial_contacts(settings), "no joint strength");
    settings.bond_cohesion = 50.;
    check(law.bonds_initial_contacts(settings), "cohesion only");
    settings.bond_cohesion = 0.;
    settings.bond_tension  = 100.;
    check(law.bonds_initial_contacts(settings), "tension only");
    std::cout << "  a joint with tensile strength or cohesion bonds, one "
                 "without does not"
              << std::endl;

    // T = 100 N/m, c = 50 N/m, bond length 0.5 m: T l = 50 N, c l = 25 N.
    settings.bond_cohesion = 50.;
    const Option o         = vertex_on_edge(0.25, 0.);
    ContactState bonded    = make_state(State::locked, 0.25, 0);
    bonded.bond_length     = 0.5;
    // Does the bond hold after the trial (gap, slip)?
    const auto expect = [&](const std::string &what,
                            const double       gap,
                            const double       slip,
                            const bool         expected) {
      const bool h = law.bond_holds(o, bonded, Trial(gap, slip), settings);
      std::cout << "  " << what << ": " << (h ? "holds" : "breaks")
                << std::endl;
      check(h == expected, what);
    };
    expect("gap 1 cm: tension 10 N of T l = 50 N", 1e-2, 0., true);
    expect("gap 6 cm: tension 60 N of 50 N", 6e-2, 0., false);
    expect("slip 5 cm: shear 20 N of c l = 25 N", 0., 5e-2, true);
    expect("slip 7 cm: shear 28 N of 25 N", 0., 7e-2, false);
    expect("slip 7 cm, penetration 1 cm: shear 28 N of 25 N + mu 10 N",
           -1e-2,
           7e-2,
           true);
    expect("slip 5 cm, gap 2 cm: shear 20 N of 25 N - mu 20 N",
           2e-2,
           5e-2,
           false);
  }



  void
  energy(const ContactLaw &law)
  {
    const ContactSettings settings = make_settings();
    const Option          o        = vertex_on_edge(0.25, -1e-3);
    std::cout << "energy at the step's end" << std::endl;
    // Locked: k_n g^2 / 2 + k_s s^2 / 2 with g = -1 mm and
    // s = (0.25 - 0.2) + 0.01.
    check_value("locked, slip 1 cm in the step",
                law.energy(o,
                           make_state(State::locked, 0.2, 0),
                           Trial(-1e-3, 1e-2),
                           settings),
                0.5 * 1000. * 1e-6 + 0.5 * 400. * 0.06 * 0.06);
    check_value("sliding: the normal spring only",
                law.energy(o,
                           make_state(State::sliding, 0.2, +1),
                           Trial(-1e-3, 1e-2),
                           settings),
                0.5 * 1000. * 1e-6);

    // A trial from a solution: P moves by (1 mm, -2 mm), the edge stays.
    Vector<double> d(8);
    d[0] = 1e-3;
    d[1] = -2e-3;
    const Trial t(o, d);
    check_value("trial gap of P moved 2 mm out", t.gap, 1e-3);
    check_value("trial tangential increment", t.increment, 1e-3);
  }



  void
  registry()
  {
    std::cout << "registry" << std::endl;
    for (const std::string &name : contact_law_names())
      std::cout << "  '" << name << "'" << std::endl;
    check(default_contact_law == "penalty Coulomb", "default law");

    std::string message;
    try
      {
        create_contact_law("Hertz");
      }
    catch (const ExceptionBase &e)
      {
        message = ndda_tests::fold_whitespace(e.what());
      }
    const std::string expected =
      "Contact/Contact law: 'Hertz' is not a contact law. Known contact "
      "laws: no contact, penalty Coulomb.";
    std::cout << "  unknown name: "
              << (message.find(expected) != std::string::npos ? expected :
                                                                message)
              << std::endl;
    check(message.find(expected) != std::string::npos, "unknown law");

    ParameterHandler prm;
    prm.enter_subsection("Contact");
    declare_contact_law_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Contact\n"
                                "  subsection no contact\n"
                                "    set Note = read\n"
                                "  end\n"
                                "end\n");
    prm.enter_subsection("Contact");
    const auto law = create_contact_law("no contact", prm);
    prm.leave_subsection();
    const auto *own = dynamic_cast<const NoContact *>(law.get());
    check(own != nullptr && own->note == "read", "parameters of a law");
    std::cout << "  'no contact' read its entry Contact/no contact/Note = "
              << own->note << std::endl;
  }
} // namespace



int
main()
{
  const std::unique_ptr<ContactLaw> law =
    create_contact_law(default_contact_law);
  springs(*law);
  springs_and_energy(*law);
  classification(*law);
  bonds(*law);
  energy(*law);
  registry();
  std::cout << "OK" << std::endl;
}
