# Where the rtcli executable is: the add-on's preference, else PATH.
#
# Licence: Apache-2.0, as the rest of rtcli.
import os
import shutil

import bpy


def preferences(context=None):
    addon = (context or bpy.context).preferences.addons.get(__package__)
    return addon.preferences if addon else None


def executable(context=None):
    """(path, '') or (None, why not), for the report and the panel."""
    prefs = preferences(context)
    chosen = bpy.path.abspath(prefs.executable) if prefs is not None and prefs.executable else ''
    if chosen:
        if os.path.isfile(chosen) and os.access(chosen, os.X_OK):
            return chosen, ''
        return None, ('rtcli not found at "%s" (Preferences > Add-ons > rtcli: the rtcli executable, or empty to '
                      'use PATH)' % chosen)
    found = shutil.which('rtcli')
    if found:
        return found, ''
    return None, ('rtcli not found on PATH: build it (tools/quickstart.sh) and run "cmake --install build --prefix '
                  '~/.local", or set its path (build/rtcli) in Preferences > Add-ons > rtcli')
