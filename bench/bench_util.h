#pragma once
// Shared benchmark helpers: a console reporter that also prints, at the end,
// each benchmark's median time and its ratio to a chosen baseline.

#include <benchmark/benchmark.h>

#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace fixel::bench {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const auto& r : runs) {
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      const std::string name = r.run_name.function_name + (r.run_name.args.empty() ? "" : "/" + r.run_name.args);
      if (!medians_.count(name)) order_.push_back(name);
      medians_[name] = r.GetAdjustedRealTime();
      units_[name] = benchmark::GetTimeUnitString(r.time_unit);
    }
  }
  // Prints "name  median  ratio-to-baseline" for every benchmark whose name
  // starts with `prefix` (the ratio base is the first such benchmark).
  void PrintRatios(std::ostream& out) const {
    out << "\nmedian times and ratios (base = first benchmark of each group):\n";
    std::map<std::string, double> base;
    for (const auto& name : order_) {
      const std::string group = name.find('/') == std::string::npos ? "" : name.substr(name.find('/'));
      if (!base.count(group)) base[group] = medians_.at(name);
      out << "  " << name << "  " << medians_.at(name) << " " << units_.at(name) << "  x"
          << medians_.at(name) / base[group] << "\n";
    }
  }

 private:
  std::vector<std::string> order_;
  std::map<std::string, double> medians_;
  std::map<std::string, std::string> units_;
};

}  // namespace fixel::bench
