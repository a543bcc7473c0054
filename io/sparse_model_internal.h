// Shared by the binary and text sparse-model readers.
#pragma once

#include <string>

#include "io/sparse_model.h"

namespace msp {

// Throws InputError for duplicate ids or names, images with an unknown camera
// and tracks naming an unknown image. `ext` is ".bin" or ".txt" so the message
// names the exact file.
void CheckSparseModelReferences(const SparseModel& model, const std::string& dir,
                                const std::string& ext);

}  // namespace msp
