// A run shared by several processes (--MspStereo.shard, --MspStereo.image_list):
// each computes the passes of its own reference images, and the states of
// every image after each pass go through a PassExchange that all of them
// see (app/shared_pass_dir.h: files in the workspace), so that a
// geometric pass reads its sources' previous-pass depth wherever they were
// computed. Nothing here knows files.
#pragma once

#include <string>
#include <vector>

#include "engine/pixel_state.h"
#include "options/shard_spec.h"

namespace msp {

// Where the processes of a shared run leave and find the per-image states;
// `pass` is the index of a pass in the schedule, `view` an index into the views.
class PassExchange {
 public:
  virtual ~PassExchange() = default;
  // Saves the state whole or not at all (a reader never sees part of it).
  virtual void Save(int pass, int view, const PixelState& state) = 0;
  virtual bool Has(int pass, int view) = 0;
  // Throws std::runtime_error naming what is missing or unreadable.
  virtual PixelState Load(int pass, int view) = 0;
  // Removes one saved state; one that is not there is no error.
  virtual void Remove(int pass, int view) = 0;
  // Removes every saved state: the run is complete.
  virtual void Clear() = 0;
  // Where the states are, for the log.
  virtual std::string Where() const = 0;
};

struct SharedRun {
  PassExchange* exchange = nullptr;
  // The problems (indices into the problem list) this process computes, ascending.
  std::vector<int> owned;
  // With --MspStereo.shard: the split, so that a barrier names the shards
  // it waits for; count 0 = an image list (the owners are not known).
  ShardSpec shard{0, 0};
  // Seconds a barrier waits for the other processes before it gives up.
  double timeout_seconds = 0.0;
  std::string name;  // "shard 1/3" or "image list FILE", for the log
};

}  // namespace msp
