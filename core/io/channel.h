#pragma once
// One animated value of a mocap file: a translation or a rotation about x, y or z.
#include "skeleton/rotation.h"

namespace mgp {

struct Channel {
    bool translation = false;
    int axis = kAxisX;
};

}  // namespace mgp
