# The rtcli command line for one frame of a Blender scene: what the render engine runs, and what a
# user can run by hand on the same export (docs/blender.md prints it). Pure: no bpy here, so the
# tests can call it with plain values.
#
# Licence: Apache-2.0, as the rest of rtcli.


class RenderRequest:
    """What one frame's render needs to know, read from Blender by the engine."""

    def __init__(self, scene_file, output, frame, fps, width, height, camera=None, integrator='path', samples=64,
                 noise_threshold=0.0, max_depth=12, denoise=False, seed=0, threads=0, aa='adaptive',
                 shadow_samples=16, glossy_samples=8, aovs=()):
        self.scene_file, self.output = scene_file, output
        self.frame, self.fps, self.width, self.height = frame, fps, width, height
        self.camera, self.integrator, self.samples = camera, integrator, samples
        self.noise_threshold, self.max_depth, self.denoise, self.seed = noise_threshold, max_depth, denoise, seed
        self.threads, self.aa, self.shadow_samples, self.glossy_samples = threads, aa, shadow_samples, glossy_samples
        self.aovs = tuple(aovs)


def render_arguments(request):
    """rtcli's arguments after the executable: a float EXR of the frame, progress as lines."""
    r = request
    args = ['render', r.scene_file, '-o', r.output, '--exr-float', '--frame', str(r.frame), '--fps', repr(float(r.fps)),
            '--width', str(r.width), '--height', str(r.height), '--integrator', r.integrator,
            '--max-depth', str(r.max_depth), '--seed', str(r.seed), '--progress', 'lines']
    if r.camera:
        args += ['--camera', r.camera]
    if r.threads > 0:
        args += ['--threads', str(r.threads)]
    if r.aovs:
        args += ['--aov', ','.join(r.aovs)]
    if r.integrator == 'path':
        args += ['--spp', str(r.samples), '--noise-threshold', repr(float(r.noise_threshold))]
        if r.denoise:
            args += ['--denoise']
    else:
        args += ['--aa', r.aa, '--shadow-samples', str(r.shadow_samples), '--glossy-samples', str(r.glossy_samples)]
    return args
