#pragma once
// J′'s report object, one shape for `seat --sustained` and `push-plan`
// (src/io_sustained.cpp): decided, t_star, theta_star, on_edges, empty and,
// with a verdict, contains, why_not and hold.

#include <nlohmann/json.hpp>
#include <optional>

#include "fixel/approach.h"
#include "fixel/seat_report.h"

namespace fixel::internal {

nlohmann::ordered_json approach_json(const ApproachSet& A, const std::optional<ApproachVerdict>& verdict);

}  // namespace fixel::internal
