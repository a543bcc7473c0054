// The PassExchange of a sharded run as files in the workspace, which every
// process sees (NFS on a cluster): <stereo>/msp_shared/pass_<p>/<image>.state
// holds an image's state after pass p, written under a temporary name,
// flushed and renamed (file_util.h), so a reader finds a whole state or none;
// the file's existence is the image's done-marker. run.txt records what
// decides the results (options, problems): a process whose run differs
// stops instead of mixing its states with another run's.
#pragma once

#include <string>
#include <vector>

#include "patch_match/pass_exchange.h"

namespace msp {

class SharedPassDir : public PassExchange {
 public:
  // `dir` is created when missing; `image_names` are the views' names.
  // Throws InputError when `dir` holds another run's states (naming the first
  // line that differs and how to go on) or cannot be written.
  SharedPassDir(std::string dir, std::vector<std::string> image_names,
                const std::string& fingerprint);

  void Save(int pass, int view, const PixelState& state) override;
  bool Has(int pass, int view) override;
  PixelState Load(int pass, int view) override;
  void Remove(int pass, int view) override;
  // Also removes the temporary files of atomic writes under the folder's
  // parent (stereo/) that killed processes of the run left.
  void Clear() override;
  std::string Where() const override { return dir_; }

  std::string StatePath(int pass, int view) const;

 private:
  std::string dir_;
  std::vector<std::string> image_names_;
};

// <stereo_dir>/msp_shared
std::string SharedPassDirPath(const std::string& stereo_dir);

}  // namespace msp
