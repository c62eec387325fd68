"""What the script tests share: a results file written where a run would leave it, and a
test case with a temporary results root that runs its script (without a display)."""

import os
import subprocess
import sys
import tempfile
import unittest

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


class ScriptOnResults(unittest.TestCase):
    """A script of scripts/ (SCRIPT, its file name) run on results under self.root."""

    SCRIPT = None

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def run_script(self, *args):
        return subprocess.run([sys.executable, os.path.join(SCRIPTS, self.SCRIPT), *args], capture_output=True,
                              text=True, env=dict(os.environ, MPLBACKEND="Agg"))
