"""The README and docs/ as a newcomer meets them: every Python block of the README runs as written from the
repository's top, every relative link and picture exists, the README stays short, and the parameter tables
of docs/algorithms/ match the filters (scripts/parameter-tables --check).

    test_docs.py SOURCE_DIR BUILD_DIR [readme-python|links|parameter-tables]"""
import glob
import os
import re
import subprocess
import sys
import tempfile
import unittest

SOURCE, BUILD = sys.argv[1], sys.argv[2]
README_LIMIT = 12 * 1024


def read(path):
    with open(os.path.join(SOURCE, path), encoding="utf-8") as file:
        return file.read()


def pages():
    return ["README.md"] + sorted(os.path.relpath(p, SOURCE) for p in glob.glob(os.path.join(SOURCE, "docs", "**",
                                                                                              "*.md"), recursive=True))


class ReadmePython(unittest.TestCase):
    def test_every_block_runs_from_the_top(self):
        blocks = re.findall(r"```python\n(.*?)```", read("README.md"), re.S)
        self.assertGreater(len(blocks), 0, "the README has no Python block")
        # A copy of the repository's top: data/ as it is, an empty out/ (make demo makes it).
        top = tempfile.mkdtemp(prefix="medial-readme-")
        os.symlink(os.path.join(SOURCE, "data"), os.path.join(top, "data"))
        os.mkdir(os.path.join(top, "out"))
        for index, block in enumerate(blocks):
            run = subprocess.run([sys.executable, "-c", block], cwd=top, capture_output=True, text=True)
            self.assertEqual(run.returncode, 0, "README Python block %d failed:\n%s" % (index + 1, run.stderr))
            self.assertNotIn("Traceback", run.stderr)


class Links(unittest.TestCase):
    def test_readme_is_short(self):
        size = len(read("README.md").encode("utf-8"))
        self.assertLessEqual(size, README_LIMIT, "README.md is %d bytes; move detail to docs/" % size)

    def test_every_relative_link_and_picture_exists(self):
        missing = []
        for page in pages():
            text = re.sub(r"```.*?```", "", read(page), flags=re.S)
            for target in re.findall(r"\]\(([^)\s]+)\)", text):
                if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                    continue
                path = os.path.normpath(os.path.join(SOURCE, os.path.dirname(page), target.split("#")[0]))
                if not os.path.exists(path):
                    missing.append("%s -> %s" % (page, target))
        self.assertEqual(missing, [])

    def test_every_algorithm_page_shows_measures_and_limits(self):
        for page in glob.glob(os.path.join(SOURCE, "docs", "algorithms", "*.md")):
            text = open(page, encoding="utf-8").read()
            self.assertIn("## Limits", text, page)
            self.assertIn("bench", text, page + " names no benchmark")
            if not page.endswith("batch.md"):  # batch makes no picture of its own
                self.assertIn("![", text, page + " shows no picture")


class ParameterTables(unittest.TestCase):
    def test_tables_match_the_filters(self):
        run = subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "parameter-tables"), "--check",
                              BUILD], cwd=SOURCE, capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)


if __name__ == "__main__":
    chosen = {"readme-python": ReadmePython, "links": Links, "parameter-tables": ParameterTables}
    cases = [chosen[a] for a in sys.argv[3:]] or list(chosen.values())
    suite = unittest.TestSuite(unittest.defaultTestLoader.loadTestsFromTestCase(c) for c in cases)
    sys.exit(0 if unittest.TextTestRunner(verbosity=2).run(suite).wasSuccessful() else 1)
