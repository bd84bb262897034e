"""Render one whole engine frame with Blender Cycles (CPU): meshes, particle media, suns, ambient.

The independent whole-frame truth of `pyro bench cycles-scene` (tools/bench/bench_cycles_scene.h).
Run it headless with Blender 3.4 (Debian's `blender` package):

  blender -b --factory-startup --python content/cycles/render_scene.py -- REQUEST.json

REQUEST.json (written by the engine; every position and direction in world units):

  {"width": W, "height": H, "samples": N, "bounces": B, "seed": S, "out": "FRAME.pfm",
   "camera": {"position": [..], "target": [..], "up": [..], "fov_y_deg": F},
   "background": [r, g, b],   # seen by camera rays that leave the scene
   "ambient": [r, g, b],      # the sky's radiance for every other ray
   "suns": [{"travel": [dx, dy, dz], "radiance": [r, g, b]}, ...],
   "meshes": [{"name": N, "albedo": [r, g, b], "positions": [x, y, z, ...],
               "normals": [x, y, z, ...], "indices": [i, j, k, ...]}, ...],
   "media": {"vdb": FILE, "anisotropy": g, "albedo": [r, g, b], "color_grid": "" or NAME,
             "emission_grid": "" or NAME} or null}

Conventions (the engine's, converted here; render_volume.py's header holds the ones shared with
`pyro bench cycles` and how they were measured):

* The engine normalises a sun's radiance L so that a fully lit white thing shows L: a Lambertian
  surface facing the sun shows L (content/shaders/mesh.frag: albedo L cos), so on surfaces the
  sun's irradiance is pi L; an isotropic medium scatters L per unit of scattering coefficient
  (content/shaders/sun_scattering.glsl: 4 pi p(mu)), so in media its irradiance is 4 pi L.
  Each engine sun is therefore two Cycles suns travelling the same way, told apart by the
  light's ray visibility (Cycles lights only the closures a light is visible to): one of
  strength pi |L| for diffuse surfaces only, one of strength 4 pi |L| for volume scattering only.
  Both cast shadows through meshes and media alike.
* The ambient term: the engine adds albedo x ambient, unshadowed, to surfaces and media. In
  Cycles it is the world's radiance seen by every ray but camera rays, so the ground under a
  tower or a cloud sees less of it: a real difference the bench reports, not a convention.
* Meshes: world-space triangles with the engine's normals (custom split normals), a Diffuse BSDF
  of the mesh's albedo, two-sided as the engine shades them.
* Media: the frame's particle media voxelised by `pyro export-vdb`'s code (tools/export/
  media_voxels.h): grid "density" holds the extinction per world unit (Principled Volume
  density 1), the albedo is the media's colour (a "color" vector grid where it varies), the
  phase function Henyey-Greenstein with the scene's g, placed half a voxel back as
  render_volume.py does.
* Film: box filter of width 1, no denoising, no clamping, linear radiance out as a colour PFM
  (rows bottom first). One line "PYRO_CYCLES {json}" on stdout on success; on bad input
  "render_scene.py: error: ..." on stderr and exit status 1.
"""

import json
import math
import os
import shutil
import sys
import tempfile
import traceback
import types

import bpy
import mathutils

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_volume as rv  # noqa: E402  (Blender's Python finds it beside this script)

PROG = "render_scene.py"


def _vec3(value, where):
    if not (isinstance(value, list) and len(value) == 3 and all(isinstance(v, (int, float)) for v in value)
            and all(math.isfinite(v) for v in value)):
        raise rv.UsageError(f"{where}: three finite numbers expected, got {value!r}")
    return [float(v) for v in value]


def read_request(argv):
    if len(argv) != 1:
        raise rv.UsageError("one argument expected: the request JSON file")
    path = argv[0]
    try:
        with open(path, encoding="utf-8") as stream:
            request = json.load(stream)
    except (OSError, ValueError) as error:
        raise rv.UsageError(f"{path}: cannot read the request: {error}")
    for key in ("width", "height", "samples", "bounces", "seed"):
        if not isinstance(request.get(key), int) or request[key] < 0:
            raise rv.UsageError(f"{path}: \"{key}\": a non-negative integer expected")
    if request["width"] < 1 or request["height"] < 1 or request["samples"] < 1:
        raise rv.UsageError(f"{path}: width, height and samples must be at least 1")
    for key in ("background", "ambient"):
        request[key] = _vec3(request.get(key), f"{path}: \"{key}\"")
    for i, sun in enumerate(request.get("suns", [])):
        sun["travel"] = _vec3(sun.get("travel"), f"{path}: suns[{i}].travel")
        sun["radiance"] = _vec3(sun.get("radiance"), f"{path}: suns[{i}].radiance")
    return request


def add_mesh(entry):
    positions, normals, indices = entry["positions"], entry["normals"], entry["indices"]
    vertices = [tuple(positions[i:i + 3]) for i in range(0, len(positions), 3)]
    faces = [tuple(indices[i:i + 3]) for i in range(0, len(indices), 3)]
    mesh = bpy.data.meshes.new(entry["name"])
    mesh.from_pydata(vertices, [], faces)
    mesh.update()
    mesh.use_auto_smooth = True
    mesh.normals_split_custom_set_from_vertices([tuple(normals[i:i + 3]) for i in range(0, len(normals), 3)])
    material = bpy.data.materials.new(entry["name"])
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*entry["albedo"], 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    output = nodes.new("ShaderNodeOutputMaterial")
    output.target = "CYCLES"
    material.node_tree.links.new(diffuse.outputs["BSDF"], output.inputs["Surface"])
    mesh.materials.append(material)
    obj = bpy.data.objects.new(entry["name"], mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def add_media(media):
    """The voxelised media; returns the volume_max_steps their bounding box needs."""
    obj, voxel_size, _ = rv.load_volume(os.path.abspath(media["vdb"]), "density")
    step = rv.configure_volume_render(obj, voxel_size)
    color_grid = media.get("color_grid", "")
    albedo = media["albedo"] if not color_grid else [1.0, 1.0, 1.0]
    rv.make_material(obj, "density", 1.0, 1.0, media["anisotropy"])
    shader = next(n for n in obj.data.materials[0].node_tree.nodes if n.type == "PRINCIPLED_VOLUME")
    shader.inputs["Color"].default_value = (*albedo, 1.0)
    shader.inputs["Color Attribute"].default_value = color_grid
    if media.get("emission_grid", ""):
        add_emission(obj, media["emission_grid"])
    return min(rv.CYCLES_MAX_STEPS_LIMIT, max(1024, math.ceil(rv.bounding_diagonal(obj) / step) + 16))


def add_emission(obj, grid):
    """The vector grid's radiance per unit length, emitted beside the scattering."""
    attribute = obj.data.materials[0].node_tree.nodes.new("ShaderNodeAttribute")
    attribute.attribute_name = grid
    rv.add_glow(obj, attribute.outputs["Vector"])


def add_sun_pair(sun, index):
    """Two Cycles suns for one engine sun: pi |L| on surfaces, 4 pi |L| in media (see the header)."""
    if max(sun["radiance"]) <= 0.0 or mathutils.Vector(sun["travel"]).length == 0.0:
        return
    for part, strength, surfaces in (("surfaces", math.pi, True), ("media", 4.0 * math.pi, False)):
        obj = rv.add_sun_light(f"sun_{index}_{part}", sun["travel"], sun["radiance"], strength)
        obj.visible_camera = False
        obj.visible_diffuse = surfaces
        obj.visible_glossy = False
        obj.visible_transmission = False
        obj.visible_volume_scatter = not surfaces


def main():
    request = read_request(rv.script_argv())
    bpy.ops.wm.read_factory_settings(use_empty=True)
    for entry in request.get("meshes", []):
        add_mesh(entry)
    max_steps = 1024
    if request.get("media"):
        max_steps = add_media(request["media"])
    for i, sun in enumerate(request.get("suns", [])):
        add_sun_pair(sun, i)
    rv.add_world(request["background"], request["ambient"])
    camera = request["camera"]
    position = _vec3(camera.get("position"), "camera.position")
    far = max(1.0, mathutils.Vector(position).length) * 100.0
    rv.add_camera(position, _vec3(camera.get("target"), "camera.target"), _vec3(camera.get("up"), "camera.up"),
                  float(camera["fov_y_deg"]), far)
    settings = types.SimpleNamespace(samples=request["samples"], seed=request["seed"], bounces=request["bounces"],
                                     width=request["width"], height=request["height"])
    work_dir = tempfile.mkdtemp(prefix="pyro_cycles_scene_")
    try:
        exr_path = os.path.join(work_dir, "render.exr")
        rv.configure_render(settings, exr_path, max_steps)
        seconds = rv.render_to_exr(exr_path)
        rv.exr_to_pfm(exr_path, os.path.abspath(request["out"]), request["width"], request["height"])
    finally:
        shutil.rmtree(work_dir, ignore_errors=True)
    print("PYRO_CYCLES " + json.dumps({"seconds": round(seconds, 3), "blender": bpy.app.version_string}), flush=True)


if __name__ == "__main__":
    try:
        main()
    except rv.UsageError as error:
        print(f"{PROG}: error: {error}", file=sys.stderr)
        sys.exit(1)
    except SystemExit:
        raise
    except Exception:  # Blender would exit 0 on an uncaught exception
        traceback.print_exc()
        print(f"{PROG}: error: unexpected failure (traceback above)", file=sys.stderr)
        sys.exit(1)
