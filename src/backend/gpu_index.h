// --PatchMatchStereo.gpu_index as COLMAP reads it, and how the reference
// images are spread over the workers it names.
#pragma once

#include <string>
#include <vector>

namespace msp {

// "-1" = every device (0 .. num_devices - 1); otherwise a comma-separated
// list of device indices, one worker each (as COLMAP, an index may repeat to
// run two workers on one device). Throws std::invalid_argument naming the
// option for an empty list, a malformed or negative entry, or a device that
// does not exist.
std::vector<int> ParseGpuIndex(const std::string& text, int num_devices);

// Item n goes to worker n % num_workers: the images of a run are spread
// evenly over the workers, in order. num_workers must be positive.
std::vector<std::vector<int>> SpreadOverWorkers(int num_items, int num_workers);

}  // namespace msp
