"""Zips the add-on for Blender's Preferences > Add-ons > Install:

    python3 tools/blender/package.py [OUT.zip]     (default: build/rtcli-blender.zip)

The archive holds the folder rtcli/ (its Python files only), as Blender expects of an add-on
package. Licence: Apache-2.0, as the rest of rtcli.
"""
import os
import sys
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))


def package(out):
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    source = os.path.join(HERE, 'rtcli')
    with zipfile.ZipFile(out, 'w', zipfile.ZIP_DEFLATED) as z:
        for name in sorted(os.listdir(source)):
            if name.endswith('.py'):
                z.write(os.path.join(source, name), 'rtcli/' + name)
    return out


if __name__ == '__main__':
    repo = os.path.dirname(os.path.dirname(HERE))
    print('wrote ' + package(sys.argv[1] if len(sys.argv) > 1 else os.path.join(repo, 'build', 'rtcli-blender.zip')))
