// The pass barrier of a run shared by several processes (pass_exchange.h),
// as the pass runner uses it. After pass p a process saves the states of
// its images; before pass p + 1 it waits until every problem's image has
// its state of pass p, whoever computed it, then reads the previous-pass
// depth of the sources it does not compute from there. The states of pass
// p - 1 are dropped once every image has finished pass p: only pass p's
// computations read them. A process restarted after a crash continues
// after the last pass whose states of all its images were saved.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "base/dense_map.h"
#include "base/mvs_input.h"
#include "engine/pixel_state.h"
#include "patch_match/pass_exchange.h"

namespace msp {

class SharedPasses {
 public:
  // `run.exchange` must outlive this.
  SharedPasses(const SharedRun& run, const std::vector<View>& views,
               const std::vector<Problem>& problems);

  const std::vector<int>& Owned() const { return run_.owned; }
  const std::string& Name() const { return run_.name; }

  // The last pass before `num_passes` whose states of every owned image are
  // saved (what a restarted process continues from), -1 = none.
  int LastSavedPass(int num_passes);

  void Save(int pass, int view, const PixelState& state) { run_.exchange->Save(pass, view, state); }
  PixelState Load(int pass, int view) { return run_.exchange->Load(pass, view); }

  // Blocks until every problem's reference image has its state of `pass`
  // (`label` names the pass in messages), polling with growing sleeps and
  // honouring stop requests (StopRequested); then drops the owned images'
  // states of the pass before it. Throws std::runtime_error after the
  // timeout, naming the images (and shards) still missing.
  void WaitForPass(int pass, const std::string& label);

  // Adds to `depths` the depth after pass `pass` of each of `sources` that is
  // a reference image and not in `depths` yet (another process's: this
  // process's own are in its memory).
  void AddSourceDepths(int pass, const std::vector<int>& sources, std::map<int, DenseMap>* depths);

  // After the last pass: when every problem's image has its final maps
  // (`has_final(view)`), the saved states are removed; true when they were.
  template <typename HasFinal>
  bool ClearWhenComplete(HasFinal has_final) {
    for (const Problem& problem : problems_) {
      if (!has_final(problem.ref)) return false;
    }
    run_.exchange->Clear();
    return true;
  }

 private:
  // The problems whose image has no state of `pass` yet.
  std::vector<int> Missing(int pass) const;
  std::string DescribeMissing(const std::vector<int>& missing) const;

  SharedRun run_;
  const std::vector<View>& views_;
  const std::vector<Problem>& problems_;
  std::map<int, int> problem_of_view_;
};

}  // namespace msp
