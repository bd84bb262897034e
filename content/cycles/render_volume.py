"""Render one OpenVDB density grid with Blender Cycles (CPU) as a reference image.

An independent multiple-scattering reference for Pyrocumulus' own volume path
tracer. Run it headless with Blender 3.4 (Debian's `blender` package):

  blender -b --factory-startup --python content/cycles/render_volume.py -- \
     --vdb FILE --grid density --extinction K --albedo A --anisotropy G \
     --sun-direction DX DY DZ --light-color R G B \
     --camera-position X Y Z --camera-target X Y Z --camera-up X Y Z --fov-y DEG \
     --width W --height H --samples N --bounces B [--background R G B] [--seed S]
     --out OUT.pfm

Conventions (the engine's; the script converts them to Blender's):

* World coordinates are the VDB file's own world coordinates (Blender units =
  VDB world units): the volume object is neither rotated nor scaled, and its
  only translation undoes Cycles' half-voxel shift ("Half-voxel shift" below).
* Extinction per world unit = K * grid value; single-scattering albedo A (grey);
  Henyey-Greenstein phase function with asymmetry G. No emission, unless
  --temperature-grid T --emission-grid E name two more float grids of the
  file: then the medium also emits, per world unit, E * c(T) / Y(c(T)), with
  c(T) the colour of Cycles' own Blackbody node at T kelvin and Y(c) its
  luminance (Cycles' RGB to BW node): Cycles' black-body chromaticity at the
  caller's luminance per unit length (a fire's emission goes with its
  extinction, Max 1995, so E = K * density * luminance of the radiance). No
  emission where T is at most 0.
* --sun-direction is the direction the light TRAVELS (sun -> scene). The sun is
  a delta directional light (angle 0).
* --light-color L: the single-scattered radiance source is
  sigma_s * L * 4pi * p(mu) * T_light, i.e. a sun of irradiance E = 4pi * L
  (per channel) on a surface facing it.
* --background is seen only by camera rays (attenuated by the volume); the world
  lights nothing. The sun is the only light.
* --bounces B: Cycles volume bounces (0 = single scattering).
* Pixel (x, y), y = 0 the TOP row, is the pinhole ray through the pixel centre;
  vertical field of view --fov-y, square pixels; each pixel averages its own
  square (box filter of width 1). Checked by rendering small emissive spheres
  at known points in a 160x96 image: their centroids land within 0.16 px of
  the pinhole projection. The output is a colour PFM ("PF", little-endian
  float32 RGB, rows stored BOTTOM row first as the format prescribes) holding
  linear radiance.

On success one line "PYRO_CYCLES {json}" is printed to stdout. On bad input the
script prints "render_volume.py: error: ..." to stderr and Blender exits with
status 1 (verified: sys.exit() inside a --python script sets Blender's exit
status; an uncaught exception would NOT, so main() turns every exception into
exit status 1). The absence of the PYRO_CYCLES line also means failure.

Input requirement: the density must be stored in LEAF VOXELS. Blender 3.4's
Cycles renders nothing for density held in active tiles (e.g. the core of the
Disney cloud); voxelise tiles into leaves (with OpenVDB) before calling this.

Sun strength (measured with Debian's Blender 3.4.1, Cycles on the CPU):
  Cycles' sun `energy` S is the irradiance on a surface facing the sun, with no
  factor pi:
  1. A white Diffuse BSDF plane (colour 1) lit head-on by a sun of energy 1,
     direct light only, renders 0.3183098 in every pixel (1/pi = 0.3183099), so
     E = pi * L_out = 1.000 * S.
  2. An optically thin homogeneous box (Principled Volume, density 0.01, albedo
     1, depth 1 along the view, sun energy 1 at 90 degrees to the view,
     volume_bounces 0, 4096 spp) renders a mean of 7.8794e-4 against
     sigma_s * p * E * depth * (attenuation of both legs) =
     0.01 / (4 pi) * 1 * 0.990058 = 7.8786e-4 (ratio 1.0001; per-pixel sd
     8e-6). With g = 0.5 and the light travelling 45 degrees towards the camera
     it renders 1.47712e-3 against 1.47712e-3 for forward-scattering HG.
  So the engine's E = 4pi * light_color is sun energy = 4pi * light_color
  (SUN_ENERGY_PER_LIGHT_COLOR).

Half-voxel shift: OpenVDB (and the engine) put the value of voxel (i, j, k) at
world point index_to_world * (i, j, k); Cycles 3.4's grid lookup puts it at
index (i + 0.5, j + 0.5, k + 0.5), i.e. shifted by half a voxel along every
index axis. Measured on openvdb_sample_sphere_levelset.vdb (centred on the
origin, voxel 0.05) rendered as an opaque "SDF < 0" absorber: the silhouette
centroid came out at +0.0256 in x, y and z; after the correction below, at
0.0000. This script therefore translates the volume object by
-0.5 * index_to_world * (1, 1, 1) (no rotation, no scale; checked); pass
--keep-cycles-voxel-offset to leave matrix_world the exact identity.
Cross-check: the transmittance of openvdb_sample_smoke1.vdb (extinction 0.2,
albedo 0, background 1, 128x128, 64 spp) matches OpenVDB's own vdb_render
(-absorb 0.2 * voxel size, since vdb_render's coefficient is per index unit;
512x512 box-filtered to 128x128) to rms 4e-4, with ln T ratio median 0.9997;
without the correction the rms difference is 0.012 (max 0.23).

Ray-march settings: Cycles 3.4 ray-marches heterogeneous volumes with a fixed
step (jittered per ray) for camera, scattered and shadow rays, and silently
lengthens the step when a segment would need more than `volume_max_steps`
steps. The object's volume step is set in world space to half the smallest
voxel size (scene and material step rates stay 1) and volume_max_steps to
cover the bounding box diagonal at that step (at least 1024, at most Cycles'
limit 65536, with a warning if the limit bites). On the sample smoke (voxel
0.476, step 0.238, diagonal about 550 steps) a 1/8-voxel step changes the
single-scattering image mean by 0.03% and takes 5x longer. Grids are loaded at
FULL float precision (Blender's default is HALF) with voxel clipping 0, and
sampled with trilinear interpolation.
"""

import argparse
import json
import math
import os
import shutil
import sys
import tempfile
import time
import traceback

import bpy
import mathutils
import numpy as np

PROG = "render_volume.py"

# Cycles' sun energy is irradiance (see "Sun strength" above); the engine's
# light colour L stands for an irradiance of 4pi * L.
SUN_ENERGY_PER_LIGHT_COLOR = 4.0 * math.pi

# Ray-march step as a fraction of the smallest voxel size.
STEP_PER_VOXEL = 0.5
# Hard limits of the Cycles 3.4 properties we set.
CYCLES_MAX_STEPS_LIMIT = 65536
CYCLES_BOUNCE_LIMIT = 1024


class UsageError(Exception):
    """Bad input: reported as one message naming the argument or file."""


def fail(message):
    """Print an error to stderr and leave Blender with exit status 1."""
    print(f"{PROG}: error: {message}", file=sys.stderr)
    sys.stderr.flush()
    sys.stdout.flush()
    sys.exit(1)


class _ArgumentParser(argparse.ArgumentParser):
    def error(self, message):  # argparse would exit with status 2 itself
        raise UsageError(message)


def script_argv():
    """Arguments after Blender's '--' separator."""
    if "--" in sys.argv:
        return sys.argv[sys.argv.index("--") + 1:]
    return []


def parse_args(argv):
    parser = _ArgumentParser(prog=PROG, description=__doc__.splitlines()[0])
    add = parser.add_argument
    add("--vdb", required=True, help="OpenVDB file")
    add("--grid", default="density", help="float grid holding the density")
    add("--extinction", type=float, required=True, help="extinction per world unit per unit grid value")
    add("--albedo", type=float, required=True, help="single-scattering albedo in [0, 1]")
    add("--anisotropy", type=float, required=True, help="Henyey-Greenstein g in (-1, 1)")
    add("--sun-direction", type=float, nargs=3, required=True, metavar=("DX", "DY", "DZ"),
        help="direction the sunlight travels")
    add("--light-color", type=float, nargs=3, required=True, metavar=("R", "G", "B"),
        help="engine light colour; sun irradiance = 4pi * colour")
    add("--camera-position", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    add("--camera-target", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    add("--camera-up", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    add("--fov-y", type=float, required=True, help="vertical field of view in degrees")
    add("--width", type=int, required=True)
    add("--height", type=int, required=True)
    add("--samples", type=int, required=True, help="samples per pixel")
    add("--bounces", type=int, required=True, help="volume bounces (0 = single scattering)")
    add("--background", type=float, nargs=3, default=(0.0, 0.0, 0.0), metavar=("R", "G", "B"),
        help="radiance seen by camera rays that leave the scene (default 0 0 0)")
    add("--seed", type=int, default=0, help="Cycles' sampling seed (default 0)")
    add("--out", required=True, help="output colour PFM")
    add("--temperature-grid", default="",
        help="float grid of kelvin in the same file: the medium emits Cycles' black-body colour there")
    add("--emission-grid", default="",
        help="float grid of the emission's luminance per world unit (with --temperature-grid)")
    add("--keep-cycles-voxel-offset", action="store_true",
        help="do not undo Cycles' half-voxel shift (volume matrix_world = identity)")
    args = parser.parse_args(argv)
    validate(args)
    return args


def _require(condition, message):
    if not condition:
        raise UsageError(message)


def validate(args):
    numbers = {
        "--extinction": [args.extinction], "--albedo": [args.albedo],
        "--anisotropy": [args.anisotropy], "--sun-direction": args.sun_direction,
        "--light-color": args.light_color, "--camera-position": args.camera_position,
        "--camera-target": args.camera_target, "--camera-up": args.camera_up,
        "--fov-y": [args.fov_y], "--background": args.background,
    }
    for name, values in numbers.items():
        _require(all(math.isfinite(v) for v in values), f"{name}: values must be finite")
    _require(os.path.isfile(args.vdb), f"--vdb: no such file: {args.vdb}")
    _require(os.access(args.vdb, os.R_OK), f"--vdb: file not readable: {args.vdb}")
    _require(args.grid != "", "--grid: empty grid name")
    _require(bool(args.temperature_grid) == bool(args.emission_grid),
             "--temperature-grid and --emission-grid go together")
    _require(args.extinction >= 0.0, f"--extinction: must be >= 0, got {args.extinction}")
    _require(0.0 <= args.albedo <= 1.0, f"--albedo: must be in [0, 1], got {args.albedo}")
    _require(-1.0 < args.anisotropy < 1.0, f"--anisotropy: must be in (-1, 1), got {args.anisotropy}")
    _require(mathutils.Vector(args.sun_direction).length > 0.0, "--sun-direction: zero vector")
    _require(min(args.light_color) >= 0.0, "--light-color: components must be >= 0")
    _require(min(args.background) >= 0.0, "--background: components must be >= 0")
    forward = mathutils.Vector(args.camera_target) - mathutils.Vector(args.camera_position)
    _require(forward.length > 0.0, "--camera-target: equals --camera-position")
    up = mathutils.Vector(args.camera_up)
    _require(up.length > 0.0, "--camera-up: zero vector")
    _require(forward.normalized().cross(up.normalized()).length > 1e-6,
             "--camera-up: parallel to the viewing direction")
    _require(0.0 < args.fov_y < 180.0, f"--fov-y: must be in (0, 180) degrees, got {args.fov_y}")
    _require(args.width >= 1, f"--width: must be >= 1, got {args.width}")
    _require(args.height >= 1, f"--height: must be >= 1, got {args.height}")
    _require(args.samples >= 1, f"--samples: must be >= 1, got {args.samples}")
    _require(0 <= args.bounces <= CYCLES_BOUNCE_LIMIT,
             f"--bounces: must be in [0, {CYCLES_BOUNCE_LIMIT}], got {args.bounces}")
    out_dir = os.path.dirname(os.path.abspath(args.out))
    _require(os.path.isdir(out_dir), f"--out: directory does not exist: {out_dir}")
    _require(os.access(out_dir, os.W_OK), f"--out: directory not writable: {out_dir}")


def load_volume(path, grid_name, shift_back=True):
    """Create the volume object; return (object, voxel size, its translation)."""
    volume = bpy.data.volumes.new("pyro_volume")
    volume.filepath = path
    if not volume.grids.load():
        raise UsageError(f"--vdb: cannot read {path}: {volume.grids.error_message}")
    names = [grid.name for grid in volume.grids]
    grid = volume.grids.get(grid_name)
    if grid is None:
        raise UsageError(f"--grid: no grid named '{grid_name}' in {path} (grids: {names})")
    if grid.data_type != "FLOAT":
        raise UsageError(f"--grid: grid '{grid_name}' in {path} is {grid.data_type}, not FLOAT")
    # grid.matrix_object is the file's index-to-world map (object space = VDB
    # world space); its column lengths are the voxel sizes along the index axes.
    index_to_world = grid.matrix_object.to_3x3()
    voxel_size = min(index_to_world.col[i].length for i in range(3))
    if not voxel_size > 0.0:
        raise UsageError(f"--grid: grid '{grid_name}' in {path} has a degenerate transform")
    # Created directly, not with the import operator (which rotates the object
    # by 90 degrees about X). The object is neither rotated nor scaled; its only
    # translation undoes Cycles' half-voxel shift (see the header) unless
    # shift_back is False, in which case matrix_world is exactly the identity.
    offset = mathutils.Vector((0.0, 0.0, 0.0))
    if shift_back:
        offset = -0.5 * (index_to_world @ mathutils.Vector((1.0, 1.0, 1.0)))
    obj = bpy.data.objects.new("pyro_volume", volume)
    bpy.context.scene.collection.objects.link(obj)
    obj.matrix_world = mathutils.Matrix.Translation(offset)
    bpy.context.view_layer.update()
    expected = mathutils.Matrix.Translation(offset)
    if any(abs(obj.matrix_world[r][c] - expected[r][c]) > 1e-6 * max(1.0, offset.length)
           for r in range(4) for c in range(4)):
        raise RuntimeError(f"volume object's matrix_world is {obj.matrix_world}, expected {expected}")
    return obj, voxel_size, offset


def configure_volume_render(obj, voxel_size):
    """Full-precision grids, no clipping, step 1/2 voxel in world units."""
    settings = obj.data.render
    settings.precision = "FULL"
    settings.clipping = 0.0
    settings.space = "WORLD"
    settings.step_size = STEP_PER_VOXEL * voxel_size
    return settings.step_size


def bounding_diagonal(obj):
    corners = [mathutils.Vector(c) for c in obj.bound_box]
    return (corners[6] - corners[0]).length


def make_material(obj, grid_name, extinction, albedo, anisotropy):
    """Principled Volume: sigma_t = K * grid, sigma_s = A * sigma_t, HG(g)."""
    material = bpy.data.materials.new("pyro_volume")
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    shader = nodes.new("ShaderNodeVolumePrincipled")
    output = nodes.new("ShaderNodeOutputMaterial")
    output.target = "CYCLES"
    material.node_tree.links.new(shader.outputs["Volume"], output.inputs["Volume"])
    # Cycles: sigma_s = Color * Density * attr, sigma_t = (Color + (1 - Color) *
    # (1 - sqrt(AbsorptionColor))) * Density * attr, which is Density * attr for
    # a black absorption colour.
    inputs = shader.inputs
    inputs["Color"].default_value = (albedo, albedo, albedo, 1.0)
    inputs["Color Attribute"].default_value = ""
    inputs["Density"].default_value = extinction
    inputs["Density Attribute"].default_value = grid_name
    inputs["Anisotropy"].default_value = anisotropy
    inputs["Absorption Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    inputs["Emission Strength"].default_value = 0.0
    inputs["Blackbody Intensity"].default_value = 0.0
    material.cycles.homogeneous_volume = False
    material.cycles.volume_interpolation = "LINEAR"
    material.cycles.volume_sampling = "MULTIPLE_IMPORTANCE"
    material.cycles.volume_step_rate = 1.0
    obj.data.materials.append(material)


def add_glow(obj, color_socket, strength_socket=None):
    """Adds an Emission of that colour (and strength, else 1) beside the volume's scattering."""
    tree = obj.data.materials[0].node_tree
    nodes, links = tree.nodes, tree.links
    output = next(n for n in nodes if n.type == "OUTPUT_MATERIAL")
    principled = next(n for n in nodes if n.type == "PRINCIPLED_VOLUME")
    glow = nodes.new("ShaderNodeEmission")
    glow.inputs["Strength"].default_value = 1.0
    links.new(color_socket, glow.inputs["Color"])
    if strength_socket is not None:
        links.new(strength_socket, glow.inputs["Strength"])
    both = nodes.new("ShaderNodeAddShader")
    links.new(principled.outputs["Volume"], both.inputs[0])
    links.new(glow.outputs["Emission"], both.inputs[1])
    links.new(both.outputs["Shader"], output.inputs["Volume"])


def add_blackbody_emission(obj, temperature_grid, emission_grid):
    """Adds E * c(T) / Y(c(T)) emission to the volume's material (see the header)."""
    tree = obj.data.materials[0].node_tree
    nodes, links = tree.nodes, tree.links
    kelvin = nodes.new("ShaderNodeAttribute")
    kelvin.attribute_name = temperature_grid
    strength = nodes.new("ShaderNodeAttribute")
    strength.attribute_name = emission_grid
    blackbody = nodes.new("ShaderNodeBlackbody")
    links.new(kelvin.outputs["Fac"], blackbody.inputs["Temperature"])
    luminance = nodes.new("ShaderNodeRGBToBW")
    links.new(blackbody.outputs["Color"], luminance.inputs["Color"])
    floor = nodes.new("ShaderNodeMath")  # never divide by 0
    floor.operation = "MAXIMUM"
    links.new(luminance.outputs["Val"], floor.inputs[0])
    floor.inputs[1].default_value = 1e-6
    per_luminance = nodes.new("ShaderNodeMath")
    per_luminance.operation = "DIVIDE"
    links.new(strength.outputs["Fac"], per_luminance.inputs[0])
    links.new(floor.outputs["Value"], per_luminance.inputs[1])
    add_glow(obj, blackbody.outputs["Color"], per_luminance.outputs["Value"])


def add_sun_light(name, direction, light_color, energy_per_color):
    """A delta sun whose light travels along `direction`, of strength energy_per_color * colour."""
    light = bpy.data.lights.new(name, "SUN")
    light.angle = 0.0
    peak = max(light_color)
    light.color = [c / peak for c in light_color] if peak > 0.0 else (1.0, 1.0, 1.0)
    light.energy = energy_per_color * peak
    light.cycles.cast_shadow = True
    light.cycles.max_bounces = CYCLES_BOUNCE_LIMIT
    sun = bpy.data.objects.new(name, light)
    bpy.context.scene.collection.objects.link(sun)
    # A Blender sun shines along its local -Z axis.
    travel = mathutils.Vector(direction).normalized()
    sun.rotation_mode = "QUATERNION"
    sun.rotation_quaternion = travel.to_track_quat("-Z", "Y")
    return sun


def add_sun(direction, light_color):
    """A delta sun whose light travels along `direction` with irradiance 4pi*colour."""
    return add_sun_light("pyro_sun", direction, light_color, SUN_ENERGY_PER_LIGHT_COLOR).data.energy


def add_world(background, ambient=(0.0, 0.0, 0.0)):
    """World radiance `background` for camera rays only, `ambient` for all other rays."""
    world = bpy.data.worlds.new("pyro_world")
    bpy.context.scene.world = world
    world.use_nodes = True
    nodes = world.node_tree.nodes
    links = world.node_tree.links
    nodes.clear()
    light_path = nodes.new("ShaderNodeLightPath")
    mix = nodes.new("ShaderNodeMixRGB")
    mix.blend_type = "MIX"
    mix.inputs["Color1"].default_value = (*ambient, 1.0)
    mix.inputs["Color2"].default_value = (*background, 1.0)
    links.new(light_path.outputs["Is Camera Ray"], mix.inputs["Fac"])
    emitter = nodes.new("ShaderNodeBackground")
    emitter.inputs["Strength"].default_value = 1.0
    links.new(mix.outputs["Color"], emitter.inputs["Color"])
    output = nodes.new("ShaderNodeOutputWorld")
    links.new(emitter.outputs["Background"], output.inputs["Surface"])
    # A black sky is never importance-sampled as a light: it emits nothing off camera rays.
    world.cycles.sampling_method = "AUTOMATIC" if max(ambient) > 0.0 else "NONE"


def add_camera(position, target, up, fov_y_degrees, max_distance):
    """Pinhole camera at `position` looking at `target`; `up` is image-up."""
    eye = mathutils.Vector(position)
    forward = (mathutils.Vector(target) - eye).normalized()
    right = forward.cross(mathutils.Vector(up)).normalized()
    true_up = right.cross(forward)
    # Blender cameras look down local -Z with local +Y up and +X right.
    rotation = mathutils.Matrix((right, true_up, -forward)).transposed()
    camera_data = bpy.data.cameras.new("pyro_camera")
    camera_data.type = "PERSP"
    camera_data.sensor_fit = "VERTICAL"
    camera_data.angle_y = math.radians(fov_y_degrees)
    camera_data.shift_x = 0.0
    camera_data.shift_y = 0.0
    camera_data.clip_start = 1e-6 * max(1.0, max_distance)
    camera_data.clip_end = 4.0 * max_distance + 1.0
    camera = bpy.data.objects.new("pyro_camera", camera_data)
    camera.matrix_world = mathutils.Matrix.Translation(eye) @ rotation.to_4x4()
    bpy.context.scene.collection.objects.link(camera)
    bpy.context.scene.camera = camera


def configure_render(args, exr_path, max_steps):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.feature_set = "SUPPORTED"
    cycles.samples = args.samples
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.seed = args.seed
    cycles.use_animated_seed = False
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.light_sampling_threshold = 0.0
    cycles.use_guiding = False
    # Scattering order: volume_bounces; nothing else may cut a path short, and
    # Russian roulette only starts after all of them (min_*_bounces).
    cycles.volume_bounces = args.bounces
    cycles.max_bounces = CYCLES_BOUNCE_LIMIT
    cycles.min_light_bounces = args.bounces
    cycles.transparent_max_bounces = CYCLES_BOUNCE_LIMIT
    cycles.min_transparent_bounces = CYCLES_BOUNCE_LIMIT
    cycles.volume_step_rate = 1.0
    cycles.volume_max_steps = max_steps
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.film_exposure = 1.0
    render = scene.render
    render.threads_mode = "AUTO"  # all CPU threads
    render.resolution_x = args.width
    render.resolution_y = args.height
    render.resolution_percentage = 100
    render.pixel_aspect_x = 1.0
    render.pixel_aspect_y = 1.0
    render.use_border = False
    render.film_transparent = False
    render.use_persistent_data = False
    view = scene.view_settings
    view.view_transform = "Standard"
    view.look = "None"
    view.exposure = 0.0
    view.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    image = render.image_settings
    image.file_format = "OPEN_EXR"
    image.color_mode = "RGB"
    image.color_depth = "32"
    image.exr_codec = "NONE"
    render.use_file_extension = False
    render.filepath = exr_path


def render_to_exr(exr_path):
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    seconds = time.perf_counter() - start
    if not os.path.isfile(exr_path):
        raise RuntimeError(f"Cycles wrote no image to {exr_path}")
    return seconds


def exr_to_pfm(exr_path, out_path, width, height):
    """Convert the linear EXR to a colour PFM, written atomically."""
    image = bpy.data.images.load(exr_path, check_existing=False)
    try:
        if tuple(image.size) != (width, height):
            raise RuntimeError(f"rendered image is {tuple(image.size)}, expected {(width, height)}")
        pixels = np.empty(width * height * image.channels, dtype=np.float32)
        image.pixels.foreach_get(pixels)
        # Blender stores rows from the bottom up, which is the PFM row order.
        rgb = pixels.reshape(height, width, image.channels)[:, :, :3]
    finally:
        bpy.data.images.remove(image)
    rgb = np.ascontiguousarray(rgb, dtype="<f4")
    temp_path = f"{out_path}.tmp{os.getpid()}"
    try:
        with open(temp_path, "wb") as stream:
            stream.write(f"PF\n{width} {height}\n-1.0\n".encode("ascii"))
            stream.write(rgb.tobytes())
        os.replace(temp_path, out_path)
    finally:
        if os.path.exists(temp_path):
            os.remove(temp_path)


def main():
    args = parse_args(script_argv())
    bpy.ops.wm.read_factory_settings(use_empty=True)
    obj, voxel_size, offset = load_volume(os.path.abspath(args.vdb), args.grid,
                                          shift_back=not args.keep_cycles_voxel_offset)
    step = configure_volume_render(obj, voxel_size)
    diagonal = bounding_diagonal(obj)
    max_steps = max(1024, math.ceil(diagonal / step) + 16)
    if max_steps > CYCLES_MAX_STEPS_LIMIT:
        print(f"{PROG}: warning: the bounding box needs {max_steps} steps of {step:g}; Cycles "
              f"caps volume_max_steps at {CYCLES_MAX_STEPS_LIMIT} and will lengthen steps",
              file=sys.stderr)
        max_steps = CYCLES_MAX_STEPS_LIMIT
    make_material(obj, args.grid, args.extinction, args.albedo, args.anisotropy)
    if args.temperature_grid:
        for name in (args.temperature_grid, args.emission_grid):
            if obj.data.grids.get(name) is None:
                raise UsageError(f"--temperature-grid/--emission-grid: no grid named '{name}' in {args.vdb}")
        add_blackbody_emission(obj, args.temperature_grid, args.emission_grid)
    sun_energy = add_sun(args.sun_direction, args.light_color)
    add_world(args.background)
    far = max((mathutils.Vector(args.camera_position) - obj.matrix_world @ mathutils.Vector(c)).length
              for c in obj.bound_box)
    add_camera(args.camera_position, args.camera_target, args.camera_up, args.fov_y, far)
    work_dir = tempfile.mkdtemp(prefix="pyro_cycles_")
    try:
        exr_path = os.path.join(work_dir, "render.exr")
        configure_render(args, exr_path, max_steps)
        seconds = render_to_exr(exr_path)
        exr_to_pfm(exr_path, os.path.abspath(args.out), args.width, args.height)
    finally:
        shutil.rmtree(work_dir, ignore_errors=True)
    report = {
        "seconds": round(seconds, 3), "samples": args.samples, "bounces": args.bounces,
        "width": args.width, "height": args.height, "sun_energy": sun_energy,
        "step_size": step, "voxel_size": voxel_size, "volume_max_steps": max_steps,
        "volume_offset": list(offset),
        "blender": bpy.app.version_string,
    }
    print("PYRO_CYCLES " + json.dumps(report), flush=True)


if __name__ == "__main__":
    try:
        main()
    except UsageError as error:
        fail(str(error))
    except SystemExit:
        raise
    except Exception:  # Blender would exit 0 on an uncaught exception
        traceback.print_exc()
        fail("unexpected failure (traceback above)")
