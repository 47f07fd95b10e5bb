"""What every paper module of scripts/reproduce-papers uses: running shadowscope's commands, reading
their numbers back, copying their images into docs/images/papers/ and stating an entry (the paper's
claim, the reproduction, a verdict). The page (docs/papers.md) is assembled here, so every entry has
the same form and the summary table at the top is made from the entries themselves."""
import json
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

VERDICTS = ("agrees", "agrees in shape", "disagrees")
BEGIN = "<!-- paper {name}: begin (written by scripts/reproduce-papers; do not edit by hand) -->"
END = "<!-- paper {name}: end -->"
ENTRY = re.compile(r"^### (?P<label>.+?) — (?P<title>.+)$\n+\*\*Verdict: (?P<verdict>[^.*]+)\.\*\*", re.M)


class Context:
    def __init__(self, build="build", full=False):
        self.root = Path(__file__).resolve().parent.parent.parent
        self.exe = self.root / build / "app" / "shadowscope"
        if not self.exe.exists():
            subprocess.run([str(self.root / "scripts" / "build"), "release", "shadowscope"], check=True)
            self.exe = self.root / "build" / "app" / "shadowscope"
        self.full = full
        self.papers_md = self.root / "docs" / "papers.md"
        self.images = self.root / "docs" / "images" / "papers"
        self.images.mkdir(parents=True, exist_ok=True)
        self.scratch = self.root / build / "papers"
        self.sections = {}  # paper name -> markdown lines
        self.paper = None
        self.commands = []  # the commands of the entry being made

    # ---- running the tool --------------------------------------------------------------------

    def begin_paper(self, name, title, source):
        self.paper = name
        self.work = self.scratch / name
        shutil.rmtree(self.work, ignore_errors=True)
        self.work.mkdir(parents=True)
        self.sections[name] = [f"## {title}", "", f"Paper: {source}.", ""]

    def size(self, small, full):
        """An image size WxH: `small` by default, `full` (the paper's) with --full."""
        return full if self.full else small

    def run(self, *args, capture=False):
        """Runs `shadowscope ARGS` from the repository root; the command is recorded for the next
        entry's "made by" lines (with the repository-relative paths a reader can type)."""
        argv = [str(a) for a in args]
        self.commands.append("shadowscope " + " ".join(shlex.quote(self._rel(a)) for a in argv))
        done = subprocess.run([str(self.exe), *argv], cwd=self.root, text=True,
                              capture_output=True)
        if done.returncode != 0:
            sys.exit(f"reproduce-papers: `{self.commands[-1]}` failed ({done.returncode}): "
                     f"{done.stderr.strip().splitlines()[-1] if done.stderr.strip() else 'no message'}")
        return done.stdout if capture else None

    def render(self, name, *args):
        """`shadowscope render ARGS --out <scratch>/NAME`; returns (folder, metrics.json as a dict)."""
        out = self.work / name
        self.run("render", *args, "--out", out)
        metrics = out / "metrics.json"
        return out, (json.loads(metrics.read_text()) if metrics.exists() else {})

    def check(self, check_file):
        """Runs a check file (tests/papers/*.json: the same cases the test command runs) and returns
        {case name: metrics.json as a dict}; a failing case is reported, not fatal, so the page can
        say which claim no longer holds."""
        out = self.work / ("check_" + Path(check_file).stem)
        argv = ["check", str(self.root / check_file), "--out", str(out)]
        self.commands.append("shadowscope " + " ".join(shlex.quote(self._rel(a)) for a in argv))
        done = subprocess.run([str(self.exe), *argv], cwd=self.root, text=True, capture_output=True)
        if done.returncode not in (0, 1):
            sys.exit(f"reproduce-papers: `{self.commands[-1]}` failed ({done.returncode}): {done.stderr.strip()}")
        if done.returncode == 1:
            print(f"reproduce-papers: {check_file}: a case failed (see {self._rel(str(out))}/report.html)",
                  file=sys.stderr)
        cases = {}
        for metrics in out.glob("*/metrics.json"):
            cases[metrics.parent.name] = json.loads(metrics.read_text())
        return cases

    def image(self, src, name):
        """Copies an image the tool wrote into docs/images/papers/<paper>_<name> and returns the
        markdown path relative to docs/."""
        dest = self.images / f"{self.paper}_{name}"
        shutil.copyfile(src, dest)
        return f"images/papers/{dest.name}"

    # ---- the page ----------------------------------------------------------------------------

    def text(self, markdown):
        """Free text in the paper's section (e.g. which built-in scene stands in for the paper's)."""
        self.sections[self.paper] += [markdown.strip(), ""]

    def entry(self, label, title, claim, reproduction, verdict, why=""):
        """One figure or table: LABEL ("Fig. 2", "Table 1"), a short TITLE, the paper's CLAIM in one or
        two sentences (numbers as facts), the REPRODUCTION (markdown: images, a table), the VERDICT (one
        of VERDICTS) and WHY (the stated difference or the reason found; required unless it agrees).
        The commands run since the last entry are listed under it."""
        if verdict not in VERDICTS:
            sys.exit(f"reproduce-papers: {self.paper} {label}: verdict must be one of {VERDICTS}")
        if verdict != "agrees" and not why.strip():
            sys.exit(f"reproduce-papers: {self.paper} {label}: a verdict other than 'agrees' needs its reason")
        lines = [f"### {label} — {title}", "", f"**Verdict: {verdict}.**" + (f" {why.strip()}" if why else ""), "",
                 f"*The paper:* {claim.strip()}", "", reproduction.strip(), ""]
        if self.commands:
            lines += ["<details><summary>Made by</summary>", "", "```"] + self.commands + ["```", "", "</details>", ""]
        self.commands = []
        self.sections[self.paper] += lines

    def page(self, keep_others=False):
        sections = {}
        old = self.papers_md.read_text() if self.papers_md.exists() else ""
        for name in ("barroso", "scherzer", "pssm", "gmnpr"):
            if name in self.sections:
                sections[name] = "\n".join(self.sections[name]).rstrip()
            elif keep_others:
                begin, end = BEGIN.format(name=name), END.format(name=name)
                if begin in old and end in old:
                    sections[name] = old[old.index(begin) + len(begin):old.index(end)].strip()
        summary = ["| paper | figure or table | verdict |", "|---|---|---|"]
        for name, body in sections.items():
            paper = body.splitlines()[0].removeprefix("## ")
            for m in ENTRY.finditer(body):
                anchor = re.sub(r"[^a-z0-9 -]", "", f"{m['label']} — {m['title']}".lower()).replace(" ", "-")
                summary.append(f"| {paper} | [{m['label']}: {m['title']}](#{anchor}) | {m['verdict']} |")
        mode = "at the papers' sizes (`--full`)" if self.full else "at the default small sizes"
        head = ["# The papers, reproduced", "",
                "Every figure and table of the four source papers (docs/references.md) that shows something "
                "shadowscope does, made again by the tool's own commands and set beside the paper's claim, "
                "with a verdict: *agrees*, *agrees in shape* (the difference stated), or *disagrees* (the "
                "reason found). Disagreements are kept, not tuned away. The numeric claims are also `check` "
                "cases in `tests/papers/` that the test command runs, so a change that breaks a paper's "
                "result fails the tests.", "",
                f"Written by `scripts/reproduce-papers` {mode} on llvmpipe (OSMesa); "
                "`scripts/reproduce-papers --full` repeats it at the papers' sizes. Each entry lists the "
                "commands that made it.", ""] + summary + [""]
        body = []
        for name, text in sections.items():
            body += [BEGIN.format(name=name), "", text, "", END.format(name=name), ""]
        return "\n".join(head + body)

    def _rel(self, arg):
        try:
            return str(Path(arg).resolve().relative_to(self.root)) if "/" in arg else arg
        except ValueError:
            return arg
