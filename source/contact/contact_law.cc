// SPDX-License-Identifier: GPL-3.0-or-later
//
// The contact law registry (ASPECT-style plugins) and the defaults of the
// ContactLaw interface.

#include <deal.II/base/exceptions.h>

#include <ndda/contact/contact_law.h>


namespace ndda
{
  namespace contact
  {
    using namespace dealii;

    // The built-in laws, see NDDA_REGISTER_CONTACT_LAW.
    void
    link_plugin_PenaltyCoulomb();

    void
    ContactLaw::link_builtin_plugins()
    {
      link_plugin_PenaltyCoulomb();
    }



    void
    ContactLaw::parse_parameters(ParameterHandler &)
    {}



    double
    ContactLaw::anchor_on_locking(const Option &o,
                                  const ContactState &,
                                  const Trial &,
                                  const ContactSettings &) const
    {
      return o.ratio;
    }



    bool
    ContactLaw::bonds_initial_contacts(const ContactSettings &) const
    {
      return false;
    }



    bool
    ContactLaw::bond_holds(const Option &,
                           const ContactState &,
                           const Trial &,
                           const ContactSettings &) const
    {
      return false;
    }



    double
    ContactLaw::friction_dissipation(const Option &,
                                     const ContactState &,
                                     const Trial &,
                                     const ContactSettings &) const
    {
      return 0.;
    }



    bool
    ContactLaw::force_lags(const Option &,
                           const ContactState &,
                           const Trial &,
                           const ContactSettings &) const
    {
      return false;
    }



    bool
    ContactLaw::forces_may_lag() const
    {
      return true;
    }



    void
    register_contact_law(const std::string &name,
                         const std::string &description,
                         void (*declare_parameters)(ParameterHandler &),
                         std::unique_ptr<ContactLaw> (*create)())
    {
      ContactLawRegistry::add(name, description, declare_parameters, create);
    }



    std::vector<std::string>
    contact_law_names()
    {
      return ContactLawRegistry::names();
    }



    std::string
    contact_law_description(const std::string &name)
    {
      const auto &laws  = ContactLawRegistry::registered();
      const auto  found = laws.find(name);
      if (found == laws.end())
        ContactLawRegistry::create(name); // throws, naming the known laws
      return found->second.description;
    }



    void
    declare_contact_law_parameters(ParameterHandler &prm)
    {
      ContactLawRegistry::declare_parameters(prm);
    }



    std::unique_ptr<ContactLaw>
    create_contact_law(const std::string &name)
    {
      return ContactLawRegistry::create(name);
    }



    std::unique_ptr<ContactLaw>
    create_contact_law(const std::string &name, ParameterHandler &prm)
    {
      return ContactLawRegistry::create_and_parse(name, prm);
    }
  } // namespace contact
} // namespace ndda
