// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_base_plugin_registry_h
#define ndda_base_plugin_registry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  /**
   * The registry of one extension point (ASPECT's plugin pattern): every
   * plugin of the interface @p Interface is registered under a name with a
   * description (which documents the `.prm` entry that selects it), a
   * function that declares its own parameters, and a factory.
   *
   * @p Interface provides
   * - `static const char *plugin_kind()` and `plugin_kinds()`: what a
   *   plugin is called in messages, singular and plural ("fracture
   *   criterion", "fracture criteria"),
   * - `static const char *selection_entry()`: the `.prm` entry that
   *   selects a plugin ("Fracture/Criterion", ...), for messages,
   * - `static void link_builtin_plugins()`: calls one function in the
   *   translation unit of each built-in plugin. ndda is a static library:
   *   the linker takes an object file from it only if something calls into
   *   that file, so without this call a program would not contain the
   *   built-in plugins (nor their registrations). A plugin compiled into a
   *   user's program does not need it.
   *
   * Plugins register themselves with NDDA_REGISTER_PLUGIN (see below),
   * during static initialization.
   *
   * @ingroup base
   */
  template <typename Interface>
  class PluginRegistry
  {
  public:
    /** What is known of one plugin. */
    struct Entry
    {
      std::string description;
      void (*declare_parameters)(dealii::ParameterHandler &);
      std::unique_ptr<Interface> (*create)();
    };

    /**
     * Register a plugin; throws if the name is taken or contains '|'
     * (the separator of a dealii::Patterns::Selection).
     */
    static void
    add(const std::string &name,
        const std::string &description,
        void (*declare_parameters)(dealii::ParameterHandler &),
        std::unique_ptr<Interface> (*create)())
    {
      AssertThrow(entries().count(name) == 0,
                  dealii::ExcMessage(std::string("Two ") +
                                     Interface::plugin_kinds() +
                                     " are registered under the name '" +
                                     name + "'."));
      AssertThrow(name.find('|') == std::string::npos,
                  dealii::ExcMessage(std::string("The ") +
                                     Interface::plugin_kind() + " name '" +
                                     name + "' contains '|'."));
      entries()[name] = {description, declare_parameters, create};
    }

    /** Every registered plugin, by name, built-in ones included. */
    static const std::map<std::string, Entry> &
    registered()
    {
      Interface::link_builtin_plugins();
      return entries();
    }

    /** The names of all plugins, sorted. */
    static std::vector<std::string>
    names()
    {
      std::vector<std::string> result;
      for (const auto &[name, entry] : registered())
        result.push_back(name);
      return result;
    }

    /** The names joined by @p separator ('|' for a Patterns::Selection). */
    static std::string
    joined_names(const std::string &separator = "|")
    {
      std::string result;
      for (const std::string &name : names())
        result += (result.empty() ? "" : separator) + name;
      return result;
    }

    /**
     * @p introduction followed by a paragraph "'name': description" for
     * every plugin: the documentation of the selecting entry.
     */
    static std::string
    documentation(const std::string &introduction)
    {
      std::string result = introduction;
      for (const auto &[name, entry] : registered())
        result += "\n\n'" + name + "': " + entry.description;
      return result;
    }

    /**
     * Declare every plugin's parameters, each in a subsection named after
     * the plugin (in the subsection @p prm is in now).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      for (const auto &[name, entry] : registered())
        {
          prm.enter_subsection(name);
          entry.declare_parameters(prm);
          prm.leave_subsection();
        }
    }

    /**
     * Create the plugin called @p name with default parameters; throws an
     * ExcMessage naming the selecting entry, the name received and the
     * known names if there is no such plugin.
     */
    static std::unique_ptr<Interface>
    create(const std::string &name)
    {
      const auto &known = registered();
      const auto  entry = known.find(name);
      AssertThrow(entry != known.end(),
                  dealii::ExcMessage(std::string(Interface::selection_entry()) +
                                     ": '" + name + "' is not a " +
                                     Interface::plugin_kind() + ". Known " +
                                     Interface::plugin_kinds() + ": " +
                                     joined_names(", ") + "."));
      return entry->second.create();
    }

    /**
     * Create the plugin called @p name and let it read its parameters from
     * its subsection (in the subsection @p prm is in now).
     */
    static std::unique_ptr<Interface>
    create_and_parse(const std::string &name, dealii::ParameterHandler &prm)
    {
      std::unique_ptr<Interface> plugin = create(name);
      prm.enter_subsection(name);
      plugin->parse_parameters(prm);
      prm.leave_subsection();
      return plugin;
    }

  private:
    /**
     * The registry, built on first use: registrations run during static
     * initialization, in an order nobody controls.
     */
    static std::map<std::string, Entry> &
    entries()
    {
      static std::map<std::string, Entry> plugins;
      return plugins;
    }
  };

  namespace internal
  {
    /**
     * Registers @p PluginType (derived from @p Interface, default
     * constructible, with a static `declare_parameters(ParameterHandler &)`)
     * when it is constructed; one static object of this type per plugin,
     * made by NDDA_REGISTER_PLUGIN.
     */
    template <typename Interface, typename PluginType>
    struct RegisterPlugin
    {
      RegisterPlugin(const char *name, const char *description)
      {
        PluginRegistry<Interface>::add(
          name,
          description,
          &PluginType::declare_parameters,
          []() -> std::unique_ptr<Interface> {
            return std::make_unique<PluginType>();
          });
      }
    };
  } // namespace internal
} // namespace ndda

/**
 * Register the plugin @p classname of the extension point @p interface
 * under @p name with @p description. Put it at the end of the plugin's
 * `.cc` file, inside the namespace of @p classname. It also defines the
 * function `link_plugin_<classname>()` in that namespace, which the
 * interface's link_builtin_plugins() calls for the built-in plugins.
 */
#define NDDA_REGISTER_PLUGIN(interface, classname, name, description) \
  void link_plugin_##classname();                                     \
  void link_plugin_##classname()                                      \
  {}                                                                  \
  namespace                                                           \
  {                                                                   \
    const ndda::internal::RegisterPlugin<interface, classname>        \
      register_plugin_##classname(name, description);                 \
  }

#endif
