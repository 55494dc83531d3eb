"""What the gallery shows: one entry per objective and extra, in page order.

A section is a dict:
  id, title        the anchor and the heading
  what, how        a sentence on what it is, and how rtcli does it (the proposal's formula)
  scene            the scene file it renders (its "test scene")
  scenes           optional {name: scene}: renders of another scene (a variant from tools/make_gallery_scenes.py)
  renders          [(name, rtcli render options, alt text, caption)]: each becomes NAME.png
                   (or NAME.gif when the options ask for frames), with its render statistics
  compare          optional (name A, name B): shown as a before/after slider
  tables           optional [(file, heading)]: the Markdown tables under that heading of a doc, as
                   HTML (tools/gallery/tables.py), so the page shows the figures the docs hold
  images           optional [(file under docs/images/, alt text, caption)]: a figure the docs hold
                   that the gallery cannot render (another renderer's image, made by tools/cycles/)
A later capability adds its own section by adding a scene and a dict here (README, "The gallery").
"""

PROJECTIONS = [("uv", "mapped by each shape's own coordinates", "uv: each shape's own coordinates"),
               ("planar", "projected flat along the axis", "planar: straight through along z"),
               ("spherical", "projected by longitude and latitude", "spherical: longitude and latitude"),
               ("cylindrical", "projected by longitude and height", "cylindrical: longitude and height")]
FILTERS = [("nearest", "aliased far away", "Nearest texel"),
           ("bilinear", "blurred near, still shimmering far away", "Bilinear: four texels, one level"),
           ("trilinear", "smooth into the distance", "Trilinear (mip-mapped)")]

SECTIONS = [
    {"id": "primitives", "title": "1. Primitives",
     "what": "Spheres, cubes, planes, cylinders, cones and triangle meshes from glTF files.",
     "how": "Exact quadric roots in each shape's canonical object space through the inverse of its transform, "
            "bounded in z, caps as planes; the nearest valid t wins. Triangles by Möller–Trumbore.",
     "scene": "scenes/primitives.json",
     "renders": [("primitives", "", "A sphere, cube, plane, cylinders, a cone and two glTF meshes under one light",
                  "Every shape, rotated and scaled")]},
    {"id": "animation", "title": "2. Animation",
     "what": "Keyframed tracks on any node; the proposal's turntable turns the scene 3° a frame, 120 frames, a "
             "4-second loop at 30 fps, with the lights fixed so the shadows stay put.",
     "how": "Frame f shows time f / fps; each frame re-places the nodes and rebuilds only the top-level BVH.",
     "scene": "scenes/turntable.json",
     "renders": [("turntable", "--frames 0-119", "The primitives turning on a turntable, a looping GIF",
                  "The turntable as a looping GIF")]},
    {"id": "antialiasing", "title": "3. Adaptive anti-aliasing",
     "what": "Rays at pixel corners; a cell whose corners differ by more than a threshold splits in four, down to "
             "a maximum depth; the weighted average is the pixel (Whitted, after Mitchell).",
     "how": "Corner rays are shared between neighbouring cells and pixels, so a flat region costs one ray a pixel.",
     "scene": "scenes/antialias.json",
     "renders": [("aa-off", "--aa none", "Thin shapes with stair-stepped edges: one ray a pixel",
                  "Off: one ray through each pixel centre"),
                 ("aa-on", "", "The same shapes with smooth edges", "On: adaptive, corners, depth 3"),
                 ("aa-refined", "--aa-debug", "The image with the refined pixels painted green",
                  "Refined pixels in green"),
                 ("aa-centres", "--aa-positions centres", "The same with samples at cell centres",
                  "Centres instead of corners: four rays a cell, none shared")],
     "compare": ("aa-off", "aa-on")},
    {"id": "reflection", "title": "4. Reflection",
     "what": "Mirrors: r = d − 2(d·n)n, traced recursively and weighted by the specular factor, to a maximum depth.",
     "how": "Each hit adds the reflected colour times its reflectivity; max_depth bounds the ray tree.",
     "scene": "scenes/reflection.json",
     "renders": [("reflection", "", "Mirrored spheres reflecting each other", "Mirrors within mirrors")]},
    {"id": "refraction", "title": "5. Refraction",
     "what": "Snell's law between air and glass, entering or leaving by the sign of d·n; Fresnel by Schlick: "
             "R = R0 + (1 − R0)(1 − cos θ)⁵, colour = R·reflected + (1 − R)·refracted.",
     "how": "A medium stack keeps nested glass right; Beer–Lambert absorption tints thick glass.",
     "scene": "scenes/refraction.json",
     "renders": [("refraction", "", "Glass spheres of indices 1.0, 1.33, 1.5 and 2.4 before a checkerboard",
                  "Indices 1.0, 1.33, 1.5, 2.4, and tinted glass")]},
    {"id": "glossy", "title": "6. Glossy reflection",
     "what": "Several reflection rays perturbed over a square of width a perpendicular to the mirror ray, averaged; "
             "rays below the surface are discarded.",
     "how": "r' = r + iU + jV, i and j stratified over [−a/2, a/2], in a Hughes–Möller basis around r.",
     "scene": "scenes/glossy.json",
     "renders": [("glossy-off", "--no-glossy", "Mirror-sharp reflections", "Off: perfect mirrors"),
                 ("glossy-on", "", "Blurred glossy reflections of several widths", "On: widths growing to the right")]
                + [("glossy-%s" % a, "", "A polished slab reflecting three blocks, lobe width %s" % a, "a = %s" % a)
                   for a in ("0", "0.05", "0.15", "0.3")],
     "compare": ("glossy-off", "glossy-on"),
     "scenes": {"glossy-%s" % a: "scenes/gallery/glossy_%s.json" % a for a in ("0", "0.05", "0.15", "0.3")}},
    {"id": "soft-shadows", "title": "7. Soft shadows",
     "what": "A rectangular light, corner C with edges W and H; shadow rays to C + ξ₁W + ξ₂H; the fraction that "
             "gets through gives the penumbra.",
     "how": "The samples are stratified over the rectangle, keyed per point, so the noise is fine and fixed.",
     "scene": "scenes/soft_shadows.json",
     "renders": [("soft-1", "--shadow-samples 1", "A hard, noisy shadow", "1 shadow ray"),
                 ("soft-4", "--shadow-samples 4", "A banded penumbra", "4 shadow rays"),
                 ("soft-16", "--shadow-samples 16", "A smooth penumbra", "16 shadow rays"),
                 ("soft-64", "--shadow-samples 64", "A smoother penumbra", "64 shadow rays")],
     "compare": ("soft-1", "soft-64")},
    {"id": "textures", "title": "8. Texture mapping",
     "what": "An image as the diffuse colour, with UVs per shape and planar, spherical and cylindrical projections.",
     "how": "Bilinear filtering of the four texels around a point, mip-mapped (trilinear) by each ray's cone.",
     "scene": "scenes/textures.json",
     "renders": [("textures", "", "Every shape textured, natural and projected", "Natural UVs and projections")]
                + [("projection-%s" % p, "", "A sphere, cube and cylinder with a UV grid, %s" % what, caption)
                   for p, what, caption in PROJECTIONS]
                + [("filter-%s" % f, "--texture-filter %s" % f, "A receding checkered plane, %s" % what, caption)
                   for f, what, caption in FILTERS],
     "compare": ("filter-nearest", "filter-trilinear"),
     "scenes": dict([("projection-%s" % p, "scenes/gallery/projection_%s.json" % p) for p, _, _ in PROJECTIONS]
                    + [("filter-%s" % f, "scenes/receding_plane.json") for f, _, _ in FILTERS])},
    {"id": "bumps", "title": "9. Bump mapping",
     "what": "A height map B perturbs the normal: N' = N + Bu(N × Ov) − Bv(N × Ou), Bu and Bv by central "
             "differences (Blinn).",
     "how": "The bumped normal drives all lighting, reflection and refraction; normal maps work the same way.",
     "scene": "scenes/bumps.json",
     "renders": [("bumps-off", "--no-bumps", "Smooth surfaces", "Off"),
                 ("bumps-on", "", "The same surfaces embossed", "On")],
     "compare": ("bumps-off", "bumps-on")},
    {"id": "depth-of-field", "title": "Extra: depth of field",
     "what": "A thin lens: rays start on the lens disk and meet on the plane of focus.",
     "how": "Shirley–Chiu concentric samples of the lens, keyed per camera sample.",
     "scene": "scenes/depth_of_field.json",
     "renders": [("depth-of-field", "", "A ball in focus between blurred ones", "Focused on the yellow ball")]},
    {"id": "csg", "title": "Extra: constructive solid geometry",
     "what": "Union, merge, intersection and difference of shapes and closed meshes.",
     "how": "Roth's span lists along each ray, combined per operation; hits keep their operand's surface.",
     "scene": "scenes/csg.json",
     "renders": [("csg", "", "A lens, a die, a hollow sphere, merged and united glass blobs and a pipe",
                  "Lens, die, hollow sphere, merge beside union, pipe")]},
    {"id": "stereo", "title": "Extra: stereo",
     "what": "Two eyes with off-axis frusta, put together as a red-cyan anaglyph (Dubois) or side by side.",
     "how": "Parallel axes, each eye's window shifted so the convergence plane has no parallax.",
     "scene": "scenes/stereo.json",
     "renders": [("stereo-anaglyph", "", "Toys as a red-cyan anaglyph", "Anaglyph: red-cyan glasses")]},
    {"id": "panorama", "title": "Extra: 360° panoramas",
     "what": "Equirectangular cameras, and omni-directional stereo for VR viewers.",
     "how": "Longitude across, latitude down; in stereo each column's eye sits on the viewing circle.",
     "scene": "scenes/panorama.json",
     "renders": [("panorama", "--stereo none", "A room all round in one 2:1 image", "The whole room")]},
    {"id": "tone-mapping", "title": "Extra: exposure and tone mapping",
     "what": "Radiance to display: render.exposure in stops, then a tone curve per channel; clamp cuts at 1, "
             "filmic rolls highlights off with Narkowicz's ACES fit f(x) = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14).",
     "how": "core/tone_map.h, applied to every radiance image before the sRGB encoding; the adaptive sampler "
            "measures contrast after it.",
     "scene": "scenes/soft_shadows.json",
     "renders": [("tone-clamp", "--exposure 1", "The soft-shadow scene one stop brighter, its lit floor burnt to "
                  "flat white", "+1 stop, clamp: the floor clips"),
                 ("tone-filmic", "--exposure 1 --tone-map filmic", "The same one stop brighter, the floor's "
                  "falloff kept", "+1 stop, filmic: highlights roll off")],
     "compare": ("tone-clamp", "tone-filmic")},
    {"id": "path-tracing", "title": "Extra: path tracing",
     "what": "Global illumination: --integrator path renders the same scene files with light bouncing between "
             "surfaces, the background as a sky, emissive surfaces as lights, environment images sampled by "
             "luminance; energy-conserving Phong lobes, glTF's GGX, Fresnel glass; MIS, Russian roulette.",
     "how": "core/render/path_integrator.cpp, materials/bsdf.cpp, core/lights/environment.cpp "
            "(docs/rendering.md, \"Path tracing\").",
     "scene": "scenes/toys/toys.json",
     "scenes": {"cornell-box": "scenes/cornell_box.json", "cornell-16": "scenes/cornell_box.json",
                "environment": "scenes/environment.json"},
     "renders": [("toys-whitted", "--integrator whitted", "The toys by Whitted ray tracing: direct light only",
                  "Whitted (the scene as it is)"),
                 ("toys-path", "--integrator path --spp 32", "The same toys path traced: the pale sky lights the "
                  "room, surfaces light each other", "Path traced, 32 samples a pixel"),
                 ("cornell-box", "", "The Cornell box, path traced: red and green walls bleed onto white blocks",
                  "The Cornell box, 256 samples a pixel"),
                 ("cornell-16", "--spp 16", "The Cornell box at 16 samples a pixel, visibly noisy",
                  "16 samples a pixel: noise falls as 1/sqrt(samples)"),
                 ("environment", "", "Chrome, clay and glass balls lit only by an HDR sky with a small sun",
                  "Lit by an environment image (scenes/textures/sky.hdr)")],
     "compare": ("toys-whitted", "toys-path")},
    {"id": "clean-sooner", "title": "Extra: clean images sooner",
     "what": "Owen-scrambled Sobol samples, one light drawn by power among many, one light unit for both "
             "integrators, and a denoiser guided by each pixel's albedo, normal, depth and variance: the Cornell "
             "box at 16 samples a pixel before and after, denoised, and at 128.",
     "how": "core/owen_sobol.h (--sampler), core/lights/light_selection.h, core/denoise/feature_filter.h "
            "(--denoise: an edge-avoiding a-trous filter on albedo-demodulated light; the emission seen is kept "
            "as it is). docs/rendering.md, \"Clean images sooner\".",
     "scene": "scenes/cornell_box.json",
     "scenes": {"toys-16-denoised": "scenes/toys/toys.json"},
     "renders": [("cornell-16-independent", "--spp 16 --sampler independent",
                  "The Cornell box at 16 samples a pixel with independent random numbers, grainy",
                  "16 samples, independent numbers (before)"),
                 ("cornell-16-sobol", "--spp 16",
                  "The Cornell box at 16 samples a pixel with Sobol samples, finer grain",
                  "16 samples, Owen-scrambled Sobol"),
                 ("cornell-16-denoised", "--spp 16 --denoise",
                  "The same 16 samples denoised: smooth walls, sharp edges and contact shadows",
                  "16 samples, denoised"),
                 ("cornell-128", "--spp 128",
                  "The Cornell box at 128 samples a pixel, raw", "128 samples, raw"),
                 ("toys-16-denoised", "--integrator path --spp 16 --denoise",
                  "The toys path traced at 16 samples a pixel and denoised: the wallpaper and wood grain stay sharp",
                  "The toys, 16 samples, denoised: textures untouched")],
     "compare": ("cornell-16-sobol", "cornell-16-denoised"),
     "images": [("cornell-equal-time-cycles.png",
                 "The Cornell box in about one second: Cycles, rtcli, rtcli denoised",
                 "Equal time against Cycles, 160x160: Cycles 32 samples (RMSE 0.0085), rtcli 58 (0.0060), "
                 "rtcli denoised (0.0034)")],
     "tables": [("docs/rendering.md", "### Clean images sooner", 1)]},
    {"id": "gltf-materials", "title": "Extra: glTF materials as the Khronos viewer shows them",
     "what": "The ratified PBR extensions, one sphere each: clearcoat, sheen, specular (back row); anisotropy, "
             "iridescence, dispersion (front row). Path traced as the glTF specification defines each lobe; "
             "Whitted shows its documented approximation. Draco- and meshopt-compressed meshes and WebP textures "
             "load too, and --view-transform Filmic shows a render as Blender's Filmic does.",
     "how": "materials/bsdf_gltf.cpp (clearcoat GGX layer, Charlie sheen, F0/F90, anisotropic GGX, thin-film "
            "Fresnel, one wavelength per path through dispersive glass), materials/pbr_to_phong.cpp (Whitted), "
            "io/gltf/compressed_geometry.cpp, io/image/view_transform.h. docs/rendering.md, \"glTF material "
            "extensions\".",
     "scene": "scenes/material_extensions.json",
     "renders": [("extensions-path", "", "Six spheres on a checked floor under a sky: a red clear-coated ball, a "
                  "purple velvet one, a gold-tinted specular one, a brushed metal one with a stretched highlight, "
                  "a dark iridescent one and a glass one splitting light into colours",
                  "Path traced, 64 samples a pixel"),
                 ("extensions-whitted", "--integrator whitted", "The same six spheres by Whitted ray tracing",
                  "Whitted's approximation")],
     "compare": ("extensions-whitted", "extensions-path")},
    {"id": "live", "title": "Extra: edit a scene, see it live; scenes of parts; renders that continue",
     "what": "rtcli watch shows a scene rendering in the browser and renders it again at every saved change, "
             "to the scene or any file it reads; a mistake shows located above the last good picture. The cafe "
             "is a scene of parts: its materials come from an included library, and four sets of a table and "
             "two stools are one template placed four times. A path-traced render can be continued from its "
             "EXR to the pixels of one longer render (render --resume).",
     "how": "cli/watch/ (the page, served by cpp-httplib; the refining stages; io/assemble/load_cache.h keeps "
            "what did not change), io/scene/scene_sources.h (includes), io/scene/node_parser.cpp (templates), "
            "cli/render/resume_plan.h. The screenshots are taken by tools/watch_screenshots.sh as the browser "
            "test takes them. docs/command-line.md (rtcli watch), docs/scene-format.md (Includes and templates).",
     "scene": "scenes/cafe.json",
     "renders": [("cafe", "", "A cafe: four sets of a wooden table and two stools on a checked floor",
                  "scenes/cafe.json: one template placed four times, materials from an included library")],
     "images": [("watch-1-first.png", "rtcli watch showing the cafe scene in the browser",
                 "1. rtcli watch scenes/cafe.json: the page, the render done"),
                ("watch-2-edited.png", "The same page after the library's red paint was made yellow",
                 "2. library/materials.json saved: the stools yellow, a tenth of a second to the first picture"),
                ("watch-3-error.png", "The page showing a located error above the last good picture",
                 "3. A typo in library/furniture.json: the error located, the last picture kept"),
                ("watch-4-normals.png", "The page showing the normals layer after the fix",
                 "4. Fixed, and seen as its normals (?layer=normal)")]},
    {"id": "blender", "title": "Extra: rtcli inside Blender",
     "what": "A render engine add-on: choose rtcli in Blender's Render Properties and press F12; the scene goes "
             "through Blender's glTF exporter and rtcli's extras (area lights, bump maps, the world), and rtcli's "
             "float render lands in the Image Editor with its depth, normal and albedo passes. A frame is bit for "
             "bit what rtcli renders from the same scene exported by hand.",
     "how": "tools/blender/rtcli (the engine, the one exporter, the EXR reader); tests/data/blender/addon_test.py "
            "runs it in Blender, headless; the screenshot is taken under Xvfb by tools/blender/screenshot.sh as "
            "the test takes it. docs/blender.md.",
     "scene": "tests/data/blender/fixture.glb",
     "renders": [("blender-fixture", "--integrator path --spp 64 --max-depth 12",
                  "The Blender fixture: a red box and a glass ball on a bump-mapped floor under a softbox",
                  "The test's Blender scene, exported by tools/blender_export.py, path traced by rtcli")],
     "images": [("blender-addon.png", "Blender 3.4 showing an rtcli render in its Image Editor, the engine's "
                 "settings in Render Properties", "F12 in Blender with the rtcli engine (headless, under Xvfb)")]},
    {"id": "final", "title": "10. The final scene: toys left behind",
     "what": "Every objective in one picture: a toy box, marbles, balls, dice, jacks, cards and blocks on a table.",
     "how": "scenes/toys/toys.json, written by tools/make_toys_scene.py.",
     "scene": "scenes/toys/toys.json",
     "renders": [("toys", "", "Toys left behind on a wooden table", "Toys left behind")]},
    {"id": "toys-turntable", "title": "The turntable",
     "what": "The toys turning, 3° a frame, 120 frames, lights fixed.",
     "how": "scenes/toys/turntable.json: a track on the tray's node. Rendered as a cluster renders it "
            "(docs/cluster.md): rtcli farm slurm splits the 120 frames into 4 chunks on a one-node Slurm "
            "cluster, and rtcli encode makes the GIF, the same bytes as a render on one machine.",
     "farm_tasks": 4,
     "scene": "scenes/toys/turntable.json",
     "renders": [("toys-turntable", "--frames 0-119", "The toys turning on a tray, a looping GIF",
                  "A 4-second loop")]},
    {"id": "speed", "title": "Speed",
     "what": "Today's ratios: rtcli against POV-Ray 3.7 on like-for-like twins of the scenes above (whole process "
             "and render time), against Cycles on path-traced samples a second, and its BVH against Embree's on "
             "the same rays. The full tables, how each came to be and the steps before are in docs/benchmark.md.",
     "how": "tools/povray/twin.py and tools/cycles/twin.py write the twins by documented rules; "
            "rtcli bench --against povray or cycles reruns the comparisons with your build.",
     # (file, heading, how many of its tables: the first, today's)
     "tables": [("docs/benchmark.md", "## Today's ratios", 1)]},
]
