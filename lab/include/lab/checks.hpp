#pragma once
// The checks of `make lab-check`: every step in the course's order, each against facet's engine
// and reference path on the course's own scenes, stopping at the first step that does not pass.

#include <string>
#include <vector>

#include "lab/steps.hpp"

namespace lab {

/// How a step stands.
enum class Outcome {
    Passed,      ///< checked, agrees with facet
    Failed,      ///< checked, disagrees: see input, expected, got and hint
    NotStarted,  ///< still the handout's stub
    Waiting,     ///< written, but a step it uses has not passed yet
    NotChecked,  ///< written, but an earlier step stopped the checks
};

/// One step's verdict, in the course's terms.
struct StepResult {
    Step step = Step::SetLookAt;
    Outcome outcome = Outcome::NotChecked;
    std::string input;     ///< what the step was given (Failed)
    std::string expected;  ///< what facet computes (Failed)
    std::string got;       ///< what the step returned (Failed)
    std::string hint;      ///< the likely mistake (Failed), or what is missing (others)
};

/// Runs the checks with the course's data in `courseDir` (the folder of example0.scene).
/// An unreadable course file is a failed step whose message names the file.
std::vector<StepResult> runChecks(const std::string& courseDir);

/// "ok", "FAILED", "not started", "waiting", "not checked".
std::string_view toString(Outcome outcome);

/// The report `make lab-check` prints: one line per step, the details under the first failure.
std::string formatResults(const std::vector<StepResult>& results);

}  // namespace lab
