# The rtcli command line for one frame of a Blender scene: what the render engine runs, and what a
# user can run by hand on the same export (docs/blender.md prints it). Pure: no bpy here, so the
# tests can call it with plain values.
#
# Licence: Apache-2.0, as the rest of rtcli.
from dataclasses import dataclass


@dataclass
class RenderRequest:
    """What one frame's render needs to know, read from Blender by the engine."""
    scene_file: str
    output: str
    frame: int
    fps: float
    width: int
    height: int
    camera: str = None
    integrator: str = 'path'
    samples: int = 64
    noise_threshold: float = 0.0
    max_depth: int = 12
    denoise: bool = False
    seed: int = 0
    threads: int = 0  # 0: rtcli's default, every CPU
    aa: str = 'adaptive'
    shadow_samples: int = 16
    glossy_samples: int = 8
    aovs: tuple = ()


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
