"""The documents in the repository state their facts: none cites a file outside the repository."""
import re

from conftest import ROOT

OUTSIDE = re.compile(r"/work/|shared/reference|\.\./shared")


def test_no_document_cites_a_file_outside_the_repository():
    documents = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
    citing = [f"{path.relative_to(ROOT)}:{number}: {line.strip()}"
              for path in documents
              for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
              if OUTSIDE.search(line)]
    assert len(documents) > 3 and citing == []


def test_ci_runs_exactly_the_readme_test_command():
    """What the README tells a user to run is what CI runs (CI only installs system packages first)."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    command = next(line for line in readme.splitlines() if line.startswith("python3 -m venv") and "[test]" in line)
    ci_commands = [line for line in (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
                   if line.startswith("python3 -m venv")]
    assert ci_commands == [command]
