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
