# Blender (background, `blender -b --factory-startup --python THIS -- FILE.glb`): imports a glTF
# with Blender's own importer (bpy.ops.import_scene.gltf) and prints the world bounding box of
# its meshes in Blender's z-up frame, one line "blender: FILE size X Y Z min X Y Z max X Y Z".
# Exits 1 when the asset is not tallest along Blender's Z (glTF's +Y): lying on its side.
import sys

import bpy
import numpy
from mathutils import Vector

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which its numpy 1.24 removed
# (AttributeError in gltf2_blender_mesh.py): restore the alias it meant.
if "bool" not in numpy.__dict__:
    numpy.bool = bool

path = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=path)
lo = Vector((float("inf"),) * 3)
hi = Vector((float("-inf"),) * 3)
meshes = 0
depsgraph = bpy.context.evaluated_depsgraph_get()
for obj in bpy.context.scene.objects:
    if obj.type != "MESH":
        continue
    meshes += 1
    evaluated = obj.evaluated_get(depsgraph)
    for v in evaluated.to_mesh().vertices:
        w = evaluated.matrix_world @ v.co
        lo = Vector(map(min, lo, w))
        hi = Vector(map(max, hi, w))
    evaluated.to_mesh_clear()
size = hi - lo
print("blender: %s meshes %d size %.3f %.3f %.3f min %.3f %.3f %.3f max %.3f %.3f %.3f"
      % (path, meshes, *size, *lo, *hi))
sys.stdout.flush()
upright = meshes > 0 and size.z > size.x and size.z > size.y
sys.exit(0 if upright else 1)
