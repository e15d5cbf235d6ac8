"""Renders RISE's measured Cornell box with Blender's Cycles, on the CPU.

Run by Blender, not by python3:

  blender -b --factory-startup -t 2 --python bench/cycles/cornell_box.py -- \
      --samples 64 --seed 1 --output out.exr

It builds the scene from scratch in an empty Blender (no startup file), from
the same YAML file that RISE renders (examples/cornell-box-measured.yaml by
default), so that the two cannot drift apart: every polygon and triangle with
its vertices as they are in the file (RISE's own coordinates, millimetres, y
up: nothing is moved, only the camera is turned to look as RISE's does), the
camera's position, look-at point and vertical field of view, each material's
colour as a Diffuse BSDF's and its emission as an Emission shader's. It
refuses any key it does not translate, rather than render another scene.

The conventions, RISE's against Blender's (checked by `--emitter-check` and
by the two converged references agreeing, see run.sh):
  - RISE's `fov` is the vertical field of view (src/scene/camera.cpp:
    halfHeight = tan(fov / 2), the width follows the aspect); Blender's
    camera is fitted vertically to the same angle. The film is square anyway.
  - RISE's image looks along look_at - position with `right` =
    forward x up (right-handed): from z = -800 towards +z, with y up, the
    image's right is -x (the green wall at x = 0 on the right, as in
    Cornell's photograph). Blender's camera looks along its local -Z with
    local +Y up and +X right, so its rotation is the matrix whose columns are
    RISE's right, up and -forward.
  - RISE's Lambertian BRDF is kd * color / pi; Cycles' Diffuse BSDF of
    colour c (roughness 0: Lambert, not Oren-Nayar) is c / pi: c = kd * color.
  - RISE's `emission` is radiance, the same on both sides of the surface;
    Cycles' Emission shader of colour c and strength 1 on a mesh is radiance
    c in the same units, from both sides: what a camera ray sees is c.
  - RISE's path tracer uses no ambient term (the file's `ambient` is for the
    classic algorithms) and the file has no point lights: only the panel
    lights the room. A material that both emits and has kd > 0 (the panel,
    kd 1, colour 0.78) also reflects: Emission + Diffuse BSDF here.
  - RISE's pixels are the mean of their own samples (a box filter one pixel
    wide, the default); Cycles is given its box filter of width 1 pixel.
  - RISE writes linear floats to OpenEXR; so does Blender (its view
    transform, set to Standard with no look, only touches displayed or
    8-bit images).

It prints, for the driver (bench/cycles/run.sh) to read:
  build_seconds   building the scene in Python, after Blender started
  render_seconds  bpy.ops.render.render: Cycles' scene sync, BVH build and
                  path tracing, into the render result
  write_seconds   saving the OpenEXR file
Blender's own status lines (on standard output) give Cycles' clock at
"Sample 0/N", when its scene sync and BVH build are done, and at "Finished":
the driver reads the path tracing's time from them. The whole process,
Blender's start-up included, is timed by the driver too.
"""

import argparse
import math
import sys
import time

import bpy
import yaml
from mathutils import Matrix, Vector

# Keys of the YAML file this script turns into Blender's; any other is refused.
CAMERA_KEYS = {"position", "look_at", "up", "fov"}
MATERIAL_KEYS = {"color", "kd", "emission"}
# ka and the ambient colour matter only to the classic algorithms, not to a
# path tracer; they are accepted and ignored.
IGNORED_MATERIAL_KEYS = {"ka"}


def parse_arguments():
    argv = sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="cornell_box.py", description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default="examples/cornell-box-measured.yaml")
    parser.add_argument("--samples", type=int, required=True, help="samples a pixel, fixed")
    parser.add_argument("--seed", type=int, default=0, help="Cycles' seed (not animated)")
    parser.add_argument("--output", required=True, help="the OpenEXR file to write")
    parser.add_argument("--width", type=int, default=512)
    parser.add_argument("--height", type=int, default=512)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument(
        "--max-bounces", type=int, default=64, help="total and diffuse bounces (RISE: --max-depth)"
    )
    parser.add_argument(
        "--split-emitters",
        type=int,
        default=1,
        metavar="N",
        help="a diagnostic: cut each emitting quadrilateral into N x N smaller ones (the same "
        "surface), so that Cycles samples its light by area, not by solid angle, from "
        "anywhere farther than a small one's size (see bench/README.md)",
    )
    parser.add_argument(
        "--emitter-check",
        action="store_true",
        help="render only the emitting surfaces, each as an Emission shader alone, "
        "to check that a camera ray sees its colour as the pixel's value",
    )
    parser.add_argument(
        "--rise-scene",
        metavar="FILE",
        help="with --emitter-check: also write the same emitters-only scene for RISE "
        "(each emitter's material with kd 0: emission alone) to FILE",
    )
    return parser.parse_args(argv)


def vector(values, what):
    if not (isinstance(values, list) and len(values) == 3):
        sys.exit(f"cornell_box.py: {what} should be three numbers, not {values!r}")
    return Vector([float(v) for v in values])


def read_scene(path):
    with open(path, encoding="utf-8") as file:
        scene = yaml.safe_load(file)
    unknown = set(scene) - {"image", "camera", "ambient", "materials", "objects"}
    if unknown:
        sys.exit(f"cornell_box.py: {path}: keys this script does not translate: {sorted(unknown)}")
    if set(scene["camera"]) - CAMERA_KEYS:
        sys.exit(f"cornell_box.py: camera keys not translated: {set(scene['camera']) - CAMERA_KEYS}")
    for name, material in scene["materials"].items():
        extra = set(material) - MATERIAL_KEYS - IGNORED_MATERIAL_KEYS
        if extra:
            sys.exit(f"cornell_box.py: material {name}: keys not translated: {sorted(extra)}")
    return scene


def write_emitters_scene(scene, path):
    """The scene with only its emitting objects, each of a material that
    only emits (kd 0), for RISE: what it and Cycles see of them directly."""
    emitting = {n for n, m in scene["materials"].items() if "emission" in m}
    only = {key: scene[key] for key in ("image", "camera") if key in scene}
    only["materials"] = {n: {"color": [1, 1, 1], "kd": 0, "emission": scene["materials"][n]["emission"]}
                         for n in sorted(emitting)}
    only["objects"] = [o for o in scene["objects"] if next(iter(o.values()))["material"] in emitting]
    with open(path, "w", encoding="utf-8") as file:
        file.write("# Written by bench/cycles/cornell_box.py --emitter-check: the emitters alone.\n")
        yaml.safe_dump(only, file, default_flow_style=None, sort_keys=False)


def clear_everything():
    # --factory-startup still brings a cube, a lamp and a camera: remove them
    # and every data block they used.
    for collection in (bpy.data.objects, bpy.data.meshes, bpy.data.lights, bpy.data.cameras,
                       bpy.data.materials, bpy.data.worlds):
        for block in list(collection):
            collection.remove(block)


def make_material(name, spec, emitter_check):
    """A Diffuse BSDF of colour kd * color, plus an Emission of the
    material's emission colour at strength 1 when it has one."""
    color = vector(spec.get("color", [1, 1, 1]), f"material {name}'s color")
    kd = float(spec.get("kd", 0.9))  # RISE's default kd (src/scene/material.hpp)
    emission = vector(spec["emission"], f"material {name}'s emission") if "emission" in spec else None
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    output.target = "CYCLES"
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    albedo = kd * color
    diffuse.inputs["Color"].default_value = (albedo.x, albedo.y, albedo.z, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
    shader = diffuse.outputs["BSDF"]
    if emission is not None:
        emit = nodes.new("ShaderNodeEmission")
        emit.inputs["Color"].default_value = (emission.x, emission.y, emission.z, 1.0)
        emit.inputs["Strength"].default_value = 1.0
        if emitter_check or kd == 0.0:
            shader = emit.outputs["Emission"]
        else:
            add = nodes.new("ShaderNodeAddShader")
            links.new(diffuse.outputs["BSDF"], add.inputs[0])
            links.new(emit.outputs["Emission"], add.inputs[1])
            shader = add.outputs["Shader"]
        # Sampled by shadow rays and by the BSDF's rays, weighted by multiple
        # importance sampling, as RISE's path tracer does by default.
        material.cycles.sample_as_light = True
    links.new(shader, output.inputs["Surface"])
    return material


def split_quadrilateral(corners, n):
    """The planar quadrilateral cut into n x n, the same surface: vertices and faces."""
    a, b, c, d = corners
    vertices = []
    for j in range(n + 1):
        v = j / n
        for i in range(n + 1):
            u = i / n
            vertices.append((1 - v) * ((1 - u) * a + u * b) + v * ((1 - u) * d + u * c))
    row = n + 1
    faces = [[j * row + i, j * row + i + 1, (j + 1) * row + i + 1, (j + 1) * row + i]
             for j in range(n) for i in range(n)]
    return vertices, faces


def add_objects(scene, materials, emitter_check, split=1):
    """One Blender object for each polygon or triangle of the file, its
    vertices as they are: a planar convex n-gon (RISE checks that each
    polygon is one) is the same surface however Cycles cuts it into
    triangles."""
    count = 0
    for index, entry in enumerate(scene["objects"]):
        if len(entry) != 1 or next(iter(entry)) not in ("polygon", "triangle"):
            sys.exit(f"cornell_box.py: object {index} is not a polygon or a triangle: {entry}")
        kind, spec = next(iter(entry.items()))
        if set(spec) - {"vertices", "material"}:
            sys.exit(f"cornell_box.py: object {index}: keys not translated: {sorted(spec)}")
        if emitter_check and "emission" not in scene["materials"][spec["material"]]:
            continue
        vertices = [vector(v, f"object {index}'s vertex") for v in spec["vertices"]]
        if kind == "triangle" and len(vertices) != 3:
            sys.exit(f"cornell_box.py: triangle {index} has {len(vertices)} vertices")
        emits = "emission" in scene["materials"][spec["material"]]
        if emits and split > 1 and len(vertices) == 4:
            vertices, faces = split_quadrilateral(vertices, split)
        else:
            faces = [list(range(len(vertices)))]
        mesh = bpy.data.meshes.new(f"{kind}{index}")
        mesh.from_pydata(vertices, [], faces)
        mesh.validate()
        mesh.materials.append(materials[spec["material"]])
        obj = bpy.data.objects.new(f"{kind}{index}-{spec['material']}", mesh)
        obj.visible_camera = True  # the panel too: the camera sees it glow
        bpy.context.scene.collection.objects.link(obj)
        count += 1
    return count


def add_camera(scene, width, height):
    spec = scene["camera"]
    position = vector(spec["position"], "camera position")
    look_at = vector(spec["look_at"], "camera look_at")
    up = vector(spec.get("up", [0, 1, 0]), "camera up")
    forward = (look_at - position).normalized()
    # As src/scene/camera.cpp: right = forward x up, then up again = right x forward.
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    rotation = Matrix((right, true_up, -forward)).transposed()  # columns: local X, Y, Z
    camera = bpy.data.cameras.new("camera")
    camera.type = "PERSP"
    camera.sensor_fit = "VERTICAL"
    camera.angle_y = math.radians(float(spec.get("fov", 50.0)))  # RISE's default fov
    camera.shift_x = camera.shift_y = 0.0
    # The scene is in millimetres: Blender's default clipping (0.1 to 100
    # units) would cut it.
    camera.clip_start = 1e-3
    camera.clip_end = 1e6
    obj = bpy.data.objects.new("camera", camera)
    obj.matrix_world = Matrix.Translation(position) @ rotation.to_4x4()
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj
    return camera


def configure_render(args, background):
    scene = bpy.context.scene
    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x, render.resolution_y = args.width, args.height
    render.resolution_percentage = 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1.0
    render.threads_mode = "FIXED"
    render.threads = args.threads
    render.film_transparent = False
    render.use_persistent_data = False
    render.use_border = False

    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.feature_set = "SUPPORTED"
    cycles.shading_system = False  # SVM, not OSL
    cycles.samples = args.samples
    cycles.seed = args.seed
    cycles.use_animated_seed = False
    cycles.sample_offset = 0
    cycles.time_limit = 0.0
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.use_preview_denoising = False
    cycles.sample_clamp_direct = 0.0  # 0: no clamping
    cycles.sample_clamp_indirect = 0.0
    cycles.light_sampling_threshold = 0.0  # every light sampled, however dim
    cycles.blur_glossy = 0.0
    # Shadow rays and BSDF samples weighed by multiple importance sampling,
    # as RISE's default. (The other two settings, shadow rays or BSDF samples
    # alone, act only in Cycles' debug builds: Debian's ignores them.)
    cycles.direct_light_sampling_type = "MULTIPLE_IMPORTANCE_SAMPLING"
    cycles.use_guiding = False  # path guiding (new in 3.4, CPU only): RISE has none
    cycles.max_bounces = args.max_bounces
    cycles.diffuse_bounces = args.max_bounces
    cycles.glossy_bounces = args.max_bounces
    cycles.transmission_bounces = args.max_bounces
    cycles.transparent_max_bounces = args.max_bounces
    cycles.volume_bounces = 0
    cycles.min_light_bounces = 0
    cycles.min_transparent_bounces = 0
    # No glossy or refractive surface in the scene: the caustics switches
    # change nothing; left on, which filters nothing.
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    cycles.use_fast_gi = False
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.film_exposure = 1.0
    cycles.use_camera_cull = False
    cycles.use_distance_cull = False
    # Newer Blenders (3.5 on) have a light tree; 3.4, Debian 12's, does not.
    if hasattr(cycles, "use_light_tree"):
        cycles.use_light_tree = True
    for layer in scene.view_layers:
        layer.cycles.use_denoising = False
        layer.samples = 0  # 0: the scene's count

    view = scene.view_settings
    view.view_transform = "Standard"
    view.look = "None"  # the "normal" look: Blender 3.4 names it None
    view.exposure = 0.0
    view.gamma = 1.0
    view.use_curve_mapping = False

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world_background = world.node_tree.nodes["Background"]
    world_background.inputs["Color"].default_value = (*background, 1.0)
    world_background.inputs["Strength"].default_value = 1.0
    scene.world = world

    image = render.image_settings
    image.file_format = "OPEN_EXR"
    image.color_mode = "RGB"
    image.color_depth = "32"  # float, not half
    image.exr_codec = "ZIP"  # lossless; bench/cycles/rmse.py reads it
    image.use_preview = False
    render.use_file_extension = False
    render.filepath = args.output


def main():
    args = parse_arguments()
    start = time.perf_counter()
    scene_file = read_scene(args.scene)
    background = scene_file.get("image", {}).get("background", [0, 0, 0])
    if args.emitter_check and args.rise_scene:
        write_emitters_scene(scene_file, args.rise_scene)
    clear_everything()
    materials = {
        name: make_material(name, spec, args.emitter_check)
        for name, spec in scene_file["materials"].items()
    }
    count = add_objects(scene_file, materials, args.emitter_check, args.split_emitters)
    camera = add_camera(scene_file, args.width, args.height)
    configure_render(args, [float(v) for v in background])
    build_seconds = time.perf_counter() - start
    print(f"objects {count}")
    print(f"camera_fov_vertical_degrees {math.degrees(camera.angle_y):.4f}")

    start = time.perf_counter()
    bpy.ops.render.render(write_still=False)
    render_seconds = time.perf_counter() - start
    result = bpy.data.images["Render Result"]
    start = time.perf_counter()
    result.save_render(args.output, scene=bpy.context.scene)
    write_seconds = time.perf_counter() - start

    print(f"build_seconds {build_seconds:.3f}")
    print(f"render_seconds {render_seconds:.3f}")
    print(f"write_seconds {write_seconds:.3f}")
    print(f"samples {bpy.context.scene.cycles.samples}")
    print(f"threads {bpy.context.scene.render.threads}")


main()
