// An open-sky scene: two building facades meeting at a corner, a tower behind
// them, a tree and a road, under open sky that reaches the top and side
// borders of every view (its pixels' ground truth is empty). The views look
// at it from the street with the rig of StreetRig: the sky's outline is
// rooflines, a tower's sides and a tree's crown, not a window frame.
//
// World frame as MakeRoomScene's: metres, z up, the road is z = 0, the
// facades are the planes x = 0 and y = 0 seen from x, y > 0.
#pragma once

#include "tools/scene/camera_rig.h"
#include "tools/scene/scene.h"

namespace msp {
namespace scene {

Scene MakeStreetScene(SkyKind sky);

// The rig of MakeStreetScene: `rig` (image size, number of views) aimed
// higher than the room's, so the upper part of every view is sky.
RigOptions StreetRig(RigOptions rig);

}  // namespace scene
}  // namespace msp
