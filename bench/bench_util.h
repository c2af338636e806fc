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
  // Prints "name  median  ratio" for every benchmark; the ratio is to the
  // first benchmark of the run (each program lists its baseline first).
  void PrintRatios(std::ostream& out) const {
    out << "\nmedian times and ratios to the first benchmark:\n";
    for (const auto& name : order_)
      out << "  " << name << "  " << medians_.at(name) << " " << units_.at(name) << "  x"
          << medians_.at(name) / medians_.at(order_.front()) << "\n";
  }

 private:
  std::vector<std::string> order_;
  std::map<std::string, double> medians_;
  std::map<std::string, std::string> units_;
};

}  // namespace fixel::bench
