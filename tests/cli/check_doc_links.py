"""check_doc_links.py ROOT [--pages-only]: every relative link of every Markdown file under ROOT
points to something that exists (a file or a folder, resolved from the linking file). With
--pages-only, only links to pages and images (.md, .png) are checked: an installed copy of the
documentation holds those, not the source files some pages link to. Prints one line per broken
link and exits 1 when there is one."""
import pathlib
import re
import sys

LINK = re.compile(r"\]\(([^)\s]+)\)")


def main() -> int:
    root = pathlib.Path(sys.argv[1])
    pages_only = "--pages-only" in sys.argv[2:]
    pages = sorted(p for p in root.rglob("*.md") if not any(
        part.startswith(".") or part.startswith("build") for part in p.relative_to(root).parts))
    if not pages:
        print(f"no Markdown file under {root}")
        return 1
    broken = 0
    for page in pages:
        text = page.read_text(encoding="utf-8")
        for number, line in enumerate(text.splitlines(), 1):
            for target in LINK.findall(line):
                if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                    continue  # a URL or an anchor in the same page
                path = target.split("#", 1)[0]
                if pages_only and not path.endswith((".md", ".png")):
                    continue
                if not (page.parent / path).exists():
                    print(f"{page.relative_to(root)}:{number}: broken link {target}")
                    broken += 1
    print(f"{len(pages)} pages, {broken} broken links")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
