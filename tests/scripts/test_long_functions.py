"""scripts/long_functions.py: what its scan counts as a function, and its length.

    /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""

import importlib.util
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "long_functions.py")
_spec = importlib.util.spec_from_file_location("long_functions", SCRIPT)
long_functions = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(long_functions)


def functions(text):
    return [(name, last - first + 1) for name, first, last in long_functions.scan(text)]


class Scan(unittest.TestCase):
    def test_signature_to_closing_brace(self):
        text = ("// a comment above is not counted\n"
                "template <typename T>\n"
                "int twice(T x,\n"
                "          int y) {\n"
                "  return 2 * x + y;\n"
                "}\n")
        self.assertEqual(functions(text), [("twice", 5)])

    def test_lambdas_and_local_classes_belong_to_their_function(self):
        text = ("void outer() {\n"
                "  auto f = [](int a) { return a; };\n"
                "  struct Local { int g() { return 1; } };\n"
                "  if (f(1)) { for (;;) { break; } }\n"
                "}\n")
        self.assertEqual(functions(text), [("outer", 5)])

    def test_namespaces_classes_and_members(self):
        text = ("namespace a { namespace {\n"
                "class C : public B<int> {\n"
                " public:\n"
                "  C() : x_{1}, y_(2) {\n"
                "    x_ = 3;\n"
                "  }\n"
                "  int get() const { return x_; }\n"
                " private:\n"
                "  int x_{0}, y_;\n"
                "};\n"
                "int C2::set(int v) noexcept { return v; }\n"
                "}  // namespace\n"
                "}  // namespace a\n")
        self.assertEqual(functions(text), [("C", 3), ("get", 1), ("C2::set", 1)])

    def test_braces_in_literals_comments_and_default_arguments(self):
        text = ('const char* s = "{";\n'
                "/* { */\n"
                "char c = '{';\n"
                "int table[] = {1, 2, 3};\n"
                "void f(const std::string& prefix = {}) {\n"
                '  g(R"({)", 1\'000);  // }\n'
                "}\n")
        self.assertEqual(functions(text), [("f", 3)])

    def test_offenders_and_status(self):
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "a.cpp"), "w") as f:
                f.write("void long_one() {\n" + "  x();\n" * 5 + "}\n" + "void short_one() { y(); }\n")
            run = subprocess.run([sys.executable, SCRIPT, "--function-lines", "6", "--file-lines", "7", tmp],
                                 capture_output=True, text=True)
            self.assertEqual(run.returncode, 1)
            self.assertIn("a.cpp:1: long_one: 7 lines", run.stdout)
            self.assertIn("a.cpp: 8 lines (file)", run.stdout)
            self.assertNotIn("short_one", run.stdout)
            run = subprocess.run([sys.executable, SCRIPT, "--function-lines", "7", "--file-lines", "8", tmp],
                                 capture_output=True, text=True)
            self.assertEqual((run.returncode, run.stdout), (0, ""))


if __name__ == "__main__":
    unittest.main()
