// SPDX-License-Identifier: GPL-3.0-or-later
#include <ndda/base/section_timer.h>

#include <algorithm>
#include <cstring>
#include <iomanip>
#include <sstream>

namespace ndda
{
  SectionTimer::Scope::Scope(SectionTimer &timer, const char *section)
    : timer(timer)
    , index(timer.find(section))
    , start(Clock::now())
  {}



  SectionTimer::Scope::~Scope()
  {
    auto &section = timer.sections[index];
    section.seconds +=
      std::chrono::duration<double>(Clock::now() - start).count();
    ++section.calls;
  }



  SectionTimer::SectionTimer()
    : created(Clock::now())
  {}



  unsigned int
  SectionTimer::find(const char *name)
  {
    for (unsigned int i = 0; i < sections.size(); ++i)
      if (std::strcmp(sections[i].name.c_str(), name) == 0)
        return i;
    sections.push_back({name, 0, 0.});
    return sections.size() - 1;
  }



  double
  SectionTimer::section_time(const std::string &section) const
  {
    for (const auto &s : sections)
      if (s.name == section)
        return s.seconds;
    return 0.;
  }



  void
  SectionTimer::print_summary(std::ostream &out) const
  {
    const double total =
      std::chrono::duration<double>(Clock::now() - created).count();
    std::vector<Section> sorted(sections);
    std::sort(sorted.begin(), sorted.end(), [](const auto &a, const auto &b) {
      return a.name < b.name;
    });
    std::size_t width = 42;
    for (const auto &s : sorted)
      width = std::max(width, s.name.size() + 1);
    const std::string rule = "+" + std::string(width, '-') +
                             "+-----------+------------+------------+\n";
    std::ostringstream table;
    table << "\n\n" << rule;
    table << "| " << std::left << std::setw(width - 1)
          << "Total wallclock time elapsed since start" << std::right
          << "|           |" << std::setw(10) << std::setprecision(3) << total
          << "s |            |\n";
    table << rule << "| " << std::left << std::setw(width - 1) << "Section"
          << std::right << "| no. calls |  wall time | % of total |\n"
          << rule;
    for (const auto &s : sorted)
      table << "| " << std::left << std::setw(width - 1) << s.name << std::right
            << "|" << std::setw(10) << s.calls << " |" << std::setw(10)
            << std::setprecision(3) << s.seconds << "s |" << std::setw(10)
            << std::setprecision(2) << std::fixed
            << (total > 0 ? 100. * s.seconds / total : 0.) << "% |\n"
            << std::defaultfloat;
    table << rule << std::endl;
    out << table.str();
  }
} // namespace ndda
