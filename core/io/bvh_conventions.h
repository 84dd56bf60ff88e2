#pragma once
// Naming conventions of the BVH files MotionGP meets, and how their joints map onto ASF bone
// roles (see ../shared/mocap/README.md):
//  - cgspeed-daz:            root `hip`, Poser names, ~cm, frame 1 is a rest pose;
//  - cgspeed-motionbuilder:  root `Hips`, LeftUpLeg..., ASF units, frame 1 is a T-pose;
//  - cgspeed-3dsmax:         root `Hips`, LeftHip/LeftKnee..., ASF units, no rest frame;
//  - asf-names:              ASF bone names (MotionGP's own export, ACCAD's Swagger), cm;
//  - generic:                anything else (viewable; effectors may be missing), cm.
#include <string>
#include <vector>

namespace mgp {

struct BvhConvention {
    std::string name;
    double cmPerUnit = 1.0;
    bool convertersAddRestFrame = false;
};

BvhConvention detectBvhConvention(const std::vector<std::string>& jointNames);
// The ASF bone role of a joint under a convention ("" = unmapped).
std::string boneRoleFor(const std::string& convention, const std::string& jointName);
// The bone whose start is the preferred end of `role` when a joint has several children
// (thorax → lowerneck, lwrist → lhand, ...), "" if none.
std::string mainChildRole(const std::string& role);

}  // namespace mgp
