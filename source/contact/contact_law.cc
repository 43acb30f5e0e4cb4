// SPDX-License-Identifier: GPL-3.0-or-later
//
// The contact law registry (ASPECT-style plugins) and the defaults of the
// ContactLaw interface.

#include <deal.II/base/exceptions.h>

#include <ndda/contact/contact_law.h>

#include <map>

namespace ndda
{
  namespace contact
  {
    using namespace dealii;

    // The built-in laws, see NDDA_REGISTER_CONTACT_LAW.
    void
    link_contact_law_PenaltyCoulomb();

    namespace
    {
      struct RegistryEntry
      {
        std::string description;
        void (*declare_parameters)(ParameterHandler &);
        std::unique_ptr<ContactLaw> (*create)();
      };

      using Registry = std::map<std::string, RegistryEntry>;

      /**
       * The registry, built on first use: registrations run during static
       * initialization, in an order nobody controls.
       */
      Registry &
      registry()
      {
        static Registry laws;
        return laws;
      }

      /** The registry, for lookups: with the built-in laws linked in. */
      const Registry &
      registered_laws()
      {
        link_contact_law_PenaltyCoulomb();
        return registry();
      }

      /** The entry of the law @p name; throws if there is none. */
      const RegistryEntry &
      entry_of(const std::string &name)
      {
        const Registry &laws  = registered_laws();
        const auto      found = laws.find(name);
        if (found == laws.end())
          {
            std::string known;
            for (const std::string &n : contact_law_names())
              known += (known.empty() ? "" : ", ") + n;
            AssertThrow(false,
                        ExcMessage("Contact: '" + name +
                                   "' is not a contact law. Known laws: " +
                                   known + "."));
          }
        return found->second;
      }
    } // namespace



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



    void
    register_contact_law(const std::string &name,
                         const std::string &description,
                         void (*declare_parameters)(ParameterHandler &),
                         std::unique_ptr<ContactLaw> (*create)())
    {
      AssertThrow(registry().count(name) == 0,
                  ExcMessage("Two contact laws are registered under the "
                             "name '" +
                             name + "'."));
      AssertThrow(name.find('|') == std::string::npos,
                  ExcMessage("The contact law name '" + name +
                             "' contains '|'."));
      registry()[name] = {description, declare_parameters, create};
    }



    std::vector<std::string>
    contact_law_names()
    {
      std::vector<std::string> names;
      for (const auto &[name, entry] : registered_laws())
        names.push_back(name);
      return names;
    }



    std::string
    contact_law_description(const std::string &name)
    {
      return entry_of(name).description;
    }



    void
    declare_contact_law_parameters(ParameterHandler &prm)
    {
      for (const auto &[name, entry] : registered_laws())
        {
          prm.enter_subsection(name);
          entry.declare_parameters(prm);
          prm.leave_subsection();
        }
    }



    std::unique_ptr<ContactLaw>
    create_contact_law(const std::string &name)
    {
      return entry_of(name).create();
    }



    std::unique_ptr<ContactLaw>
    create_contact_law(const std::string &name, ParameterHandler &prm)
    {
      std::unique_ptr<ContactLaw> law = create_contact_law(name);
      prm.enter_subsection(name);
      law->parse_parameters(prm);
      prm.leave_subsection();
      return law;
    }
  } // namespace contact
} // namespace ndda
