# Run inside Blender: blender -b --factory-startup --python-exit-code 1 -P check_gltf_import.py --
#   OUTDIR...
# Each OUTDIR (tests/gltf/export_for_check.sh) holds export.glb, export.gltf, maybe export.fbx,
# and check.json: the clip's frame count and rate, and `motiongp fk --json` of five frames. Each
# file is imported into an empty scene at the clip's rate with Blender's own glTF (or FBX)
# importer, and must give one armature, one action spanning the frame count, and every bone's head
# where our FK puts the joint of the same name, within 0.1 cm. Prints a BLENDER_GLTF_CHECK line per
# file; exits 1 if any file fails.
import json
import os
import sys

import numpy

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

import bpy

args = sys.argv[sys.argv.index("--") + 1:]


def check(path, frames, fps, fks):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    # Blender keys glTF times at the scene's rate: at the clip's own, one key per frame.
    bpy.context.scene.render.fps = int(round(fps))
    bpy.context.scene.render.fps_base = round(fps) / fps
    if path.lower().endswith(".fbx"):
        bpy.ops.import_scene.fbx(filepath=path)
    else:
        bpy.ops.import_scene.gltf(filepath=path)
    armatures = [o for o in bpy.context.scene.objects if o.type == "ARMATURE"]
    actions = list(bpy.data.actions)
    problems = []
    if len(armatures) != 1:
        problems.append(f"expected one armature, found {len(armatures)}")
    if len(actions) != 1:
        problems.append(f"expected one action, found {len(actions)}")
    elif round(actions[0].frame_range[1] - actions[0].frame_range[0]) + 1 != frames:
        problems.append(f"expected an action of {frames} frames, found range {tuple(actions[0].frame_range)}")
    worst = 0.0
    compared = 0
    # Our frame k (from 1) is the action's first frame + k - 1: the glTF importer starts at frame
    # 0 (time 0), Blender's FBX round trip at frame 1.
    first = round(actions[0].frame_range[0]) if actions else 0
    if armatures:
        arm = armatures[0]
        for fk in fks:
            bpy.context.scene.frame_set(first + fk["frame"] - 1)
            for name, want in fk["joints_cm"].items():
                pb = arm.pose.bones.get(name)
                if pb is None:
                    problems.append(f"no bone {name}")
                    continue
                h = arm.matrix_world @ pb.head
                got = (h.x * 100.0, h.z * 100.0, -h.y * 100.0)  # Blender Z up, metres -> Y up, cm
                worst = max(worst, sum((a - b) ** 2 for a, b in zip(got, want)) ** 0.5)
                compared += 1
    if compared == 0:
        problems.append("no bone compared")
    if worst > 0.1:
        problems.append(f"a bone head {worst:.4f} cm from our FK (limit 0.1 cm)")
    print("BLENDER_GLTF_CHECK " + json.dumps({
        "file": "/".join(path.rsplit("/", 2)[-2:]), "armatures": len(armatures), "actions": len(actions),
        "frame_range": list(actions[0].frame_range) if actions else None,
        "bones": len(armatures[0].data.bones) if armatures else 0,
        "joints_compared": compared, "worst_cm": worst, "problems": problems[:10]}))
    return not problems


results = []
for case in args:
    info = json.load(open(os.path.join(case, "check.json")))
    fks = [json.load(open(f)) for f in info["fk_files"]]
    for name in ("export.glb", "export.gltf", "export.fbx"):
        path = os.path.join(case, name)
        if name != "export.fbx" or os.path.exists(path):
            results.append(check(path, info["frames"], info["fps"], fks))
sys.exit(0 if results and all(results) else 1)
