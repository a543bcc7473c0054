// What the msp_stereo command needs to run as one process of a sharded run
// (--MspStereo.shard K/N or --MspStereo.image_list FILE; docs/cluster.md):
// its name, its lock and scratch folder, the problems it computes and what
// decides the run's results, which every process of the run must share.
#pragma once

#include <string>
#include <vector>

#include "io/workspace.h"
#include "options/stereo_options.h"

namespace msp {

bool IsSharded(const MspStereoOptions& msp);

// "shard K/N" or "image list FILE", for the log.
std::string ShardName(const MspStereoOptions& msp);

// A name for the shard's files: "shard-K-of-N" or "list-<file name>".
std::string ShardTag(const MspStereoOptions& msp);

// The problems (indices into workspace.problems) whose reference image is
// named in the image list `path`: one name per line as in images/ (and
// patch-match.cfg), surrounding blanks ignored, empty lines and lines
// starting with # skipped. Throws InputError naming the file and line of a
// name that is no problem's reference image, and for an unreadable or empty list.
std::vector<int> ReadImageList(const std::string& path, const Workspace& workspace);

// The problems this process computes: its shard's, or its image list's.
std::vector<int> OwnedProblems(const MspStereoOptions& msp, const Workspace& workspace);

// The options that decide the results (all but paths, threads, the log, the
// shard and previews), one `--name value` line each, then one line per
// problem (reference, sources, depth range): equal for every process of a run.
std::string SharedRunFingerprint(const StereoCommandOptions& options, const Workspace& workspace);

}  // namespace msp
