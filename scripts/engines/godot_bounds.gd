# Godot 3 (`godot3 --no-window --path PROJECT -s godot_bounds.gd`): loads res://asset.glb as the
# editor imported it (Godot's own glTF importer), instances it and prints the bounding box of its
# MeshInstances in Godot's y-up frame, one line "godot: meshes N size X Y Z min X Y Z max X Y Z".
# Quits with 1 when the asset is not tallest along Y: lying on its side.
extends SceneTree

var lo = Vector3(INF, INF, INF)
var hi = Vector3(-INF, -INF, -INF)
var meshes = 0

func visit(node, xform):
	var t = xform
	if node is Spatial:
		t = xform * node.transform
	if node is MeshInstance and node.mesh != null:
		meshes += 1
		var box = t.xform(node.mesh.get_aabb())
		lo = Vector3(min(lo.x, box.position.x), min(lo.y, box.position.y), min(lo.z, box.position.z))
		var end = box.position + box.size
		hi = Vector3(max(hi.x, end.x), max(hi.y, end.y), max(hi.z, end.z))
	for child in node.get_children():
		visit(child, t)

func _init():
	var scene = load("res://asset.glb")
	if scene == null:
		print("godot: res://asset.glb did not import")
		quit(1)
		return
	visit(scene.instance(), Transform.IDENTITY)
	var size = hi - lo
	print("godot: meshes %d size %.3f %.3f %.3f min %.3f %.3f %.3f max %.3f %.3f %.3f" % [
		meshes, size.x, size.y, size.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z])
	var upright = meshes > 0 and size.y > size.x and size.y > size.z
	quit(0 if upright else 1)
