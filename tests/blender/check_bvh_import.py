# Run inside Blender: blender -b --factory-startup --python-exit-code 1 -P check_bvh_import.py -- FILE.bvh FK.json...
# Imports FILE.bvh with Blender's own BVH importer and compares the positions it computes with
# MotionGP's FK (the JSON files of `motiongp fk --json`): every bone's head against the joint of
# the same name, and the effectors where the export uses ASF bone names. Exits 1 past 0.01 cm.
import builtins
import json
import sys

import bpy
import io_anim_bvh.import_bvh as import_bvh

# Blender 3.4's importer opens with mode 'rU', which Python 3.11 rejects: map it to 'r'.
_open = builtins.open
import_bvh.open = lambda path, mode="r", *a, **k: _open(path, "r" if mode == "rU" else mode, *a, **k)

args = sys.argv[sys.argv.index("--") + 1:]
bvh_path, fk_files = args[0], args[1:]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_anim.bvh(filepath=bvh_path, global_scale=1.0, axis_forward="-Z", axis_up="Y",
                        rotate_mode="NATIVE", update_scene_fps=True, update_scene_duration=True)
arm = next(o for o in bpy.context.scene.objects if o.type == "ARMATURE")
# Blender world (Z up) back to BVH (Y up): (x, y, z)_bvh = (x, z, -y)_blender.
to_bvh = lambda v: (v.x, v.z, -v.y)
sites = {"root": ("root", "head"), "head": ("head", "tail"), "lhand": ("lwrist", "tail"),
         "rhand": ("rwrist", "tail"), "lfoot": ("lfoot", "tail"), "rfoot": ("rfoot", "tail")}
worst = 0.0
compared = 0
report = {}
for path in fk_files:
    fk = json.load(open(path))
    frame = fk["frame"]
    bpy.context.scene.frame_set(frame)
    for name, want in fk["joints_cm"].items():
        pb = arm.pose.bones.get(name)
        if pb is None:  # a joint the export leaves out (an ASF clip's fingers and toes)
            continue
        p = to_bvh(arm.matrix_world @ pb.head)
        d = sum((a - b) ** 2 for a, b in zip(p, want)) ** 0.5
        worst = max(worst, d)
        compared += 1
    for key, (bone, end) in sites.items():
        if bone not in arm.pose.bones:  # a source-hierarchy export: its joints were compared above
            continue
        pb = arm.pose.bones[bone]
        p = to_bvh(arm.matrix_world @ getattr(pb, end))
        want = fk["positions_cm"][key]
        d = sum((a - b) ** 2 for a, b in zip(p, want)) ** 0.5
        worst = max(worst, d)
        report[f"{frame}:{key}"] = round(d, 6)
print("BLENDER_BVH_CHECK " + json.dumps({"worst_cm": worst, "frames": len(fk_files), "bones": len(arm.pose.bones),
                                        "joints_compared": compared}))
sys.exit(0 if worst < 0.01 and compared > 0 else 1)
