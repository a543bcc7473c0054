// The evaluator's outputs: a human-readable table and a JSON document.
#pragma once

#include <ostream>
#include <string>

#include "tools/evaluate/evaluate_workspace.h"

namespace msp {
namespace eval {

void PrintReport(const EvaluationResult& result, std::ostream& out);
std::string ReportJson(const EvaluationResult& result);

}  // namespace eval
}  // namespace msp
