#pragma once
// The Compare panel's "Against the ground truth" section: the samples, Measure (or a progress
// bar and Cancel while the job runs), then each method's median time and error in the view it
// was measured for, in a window of its own; clicking a row switches the viewer to that method.

#include <cstdint>

#include "accuracy_job.hpp"

namespace facet::view {

struct ViewerModel;
struct WorkspaceUi;

/// The accuracy job and what its section and table show.
struct AccuracyState {
    AccuracyJob job;                        ///< Compare: the methods against the ground truth
    int samples = kDefaultAccuracySamples;  ///< ground truth samples per axis
    bool open = false;                      ///< the section is open
    bool table = false;                     ///< the table's window is open
    std::uint64_t tableSeen = 0;            ///< reports for which the table opened by itself
    std::uint64_t announced = 0;            ///< reports announced on stdout so far
};

/// Compare's "Against the ground truth": samples, Measure, progress, the report's summary.
void accuracySection(AccuracyState& accuracy, const ViewerModel& model);

/// The ground-truth table in a window of its own (large: eight columns) over the image area,
/// when open; a clicked row's method goes to `model`'s settings.
void accuracyWindow(AccuracyState& accuracy, ViewerModel& model, WorkspaceUi& work);

/// Announces a newly finished accuracy report on stdout (scripts and tests wait for it).
void announceAccuracy(AccuracyState& accuracy);

}  // namespace facet::view
