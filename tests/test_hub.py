"""A class on JupyterHub: a real hub on the loopback address, three students and an instructor.

The hub is the `jupyterhub` package with `configurable-http-proxy` from npm (hub/package.json),
configured with the course's own settings from hub/values.yaml (hub.config and hub.extraConfig,
executed as they are), a password this test sets (DummyAuthenticator) and one home folder per
account (SimpleLocalProcessSpawner: local processes, one folder each, as a laptop cannot make
Kubernetes pods). The course reaches each student as on a real hub: nbgitpuller clones it into
the student's home from a git repository (here a bare copy of this one), while course_lib stays
the installed one.

Three students at once each: log in, start a server, pull the course, open the start page, run
a whole lesson in a kernel, record a mock exam and see it on the start page. The instructor's
kernel draws in lecture mode, the students' do not. Then: each student's progress is in their
own home and holds their exam only; the course's files are unchanged; a student's server
refuses another student's token and cookies (403); the hub refuses a wrong password; and every
process stops. The figures (hub start-up, memory per student) are printed for hub/sizing.md.
"""
import concurrent.futures
import hashlib
import json
import os
import re
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import time
import uuid
from pathlib import Path

import pytest
import requests            # with jupyterhub (the hub extra, in the test extra)
import websocket           # websocket-client, with jupyter_server
import yaml

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
STUDENTS = {"ada": [3, 7], "grace": [4, 5], "alan": [12, 15]}     # each one's exam chapters
LESSON = "ch04_projections_viewing"
COURSE = "graphics-course"           # the folder nbgitpuller clones the course into
PASSWORD = secrets.token_urlsafe(12)     # the class's shared password (a test's own)
ADMIN_PASSWORD = secrets.token_urlsafe(32)     # the instructors' (admins') own

RECORD_EXAM = """
import json
from course_lib import progress
from course_lib.exercises import mock_exam
exam = mock_exam({seed}, chapters={chapters}, n_questions=4)
for i, question in enumerate(exam):        # the concept questions right, the rest left blank
    exam.submit(i, question.source.letters[question.source.correct]
                if question.kind == "concept" else "")
progress.record_exam(exam)
print(json.dumps({{"file": str(progress.progress_path()), "chapters": [q.chapter for q in exam]}}))
"""
PROBE = """
import json, os, resource, sys
import course_lib
from course_lib import draw
status = dict(line.split(":", 1) for line in open("/proc/self/status"))
print(json.dumps({"lecture": draw.lecture_scale(), "module": course_lib.__file__,
                  "cwd": os.getcwd(), "home": os.environ["HOME"],
                  "peak_mib": int(status["VmHWM"].split()[0]) / 1024}))
"""


def test_values_yaml_is_valid_for_the_chart():
    """hub/values.yaml merged over the chart's defaults (as Helm does) passes the chart's own
    schema (both of z2jh 4.4.0, in hub/z2jh-4.4.0/), so `helm install` will take it."""
    import jsonschema

    def merge(base, over):
        out = dict(base)
        for key, value in over.items():
            out[key] = merge(out[key], value) if isinstance(value, dict) \
                and isinstance(out.get(key), dict) else value
        return out

    chart = ROOT / "hub" / "z2jh-4.4.0"
    schema = yaml.safe_load((chart / "values.schema.yaml").read_text())
    defaults = yaml.safe_load((chart / "values.yaml").read_text())
    ours = yaml.safe_load((ROOT / "hub" / "values.yaml").read_text())
    validator = jsonschema.Draft7Validator(schema)
    errors = [f"{'.'.join(map(str, e.path))}: {e.message}"
              for e in validator.iter_errors(merge(defaults, ours))]
    assert not errors, errors
    # and the schema can say no: a key the chart does not know
    assert list(validator.iter_errors(merge(defaults, {"hub": {"loadGroups": {}}})))
    # the hub's config carries the instructors' group that lecture mode reads
    config = ours["hub"]["config"]
    assert set(config["JupyterHub"]["load_groups"]["instructors"]["users"]) <= set(
        config["Authenticator"]["admin_users"])


def test_hub_image_keeps_the_course_outside_the_home_and_read_only(tmp_path):
    """repo2docker with --target-repo-dir puts the course (and the start script) outside the
    home folder a hub mounts each student's volume over; postBuild then makes it read-only.
    On Binder (the repository is the home folder) it stays writable."""
    repo2docker = BIN / "repo2docker"
    done = subprocess.run([str(repo2docker), "--no-build", "--debug", "--user-id", "1000",
                           "--user-name", "jovyan", "--target-repo-dir", "/srv/course",
                           str(ROOT)], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
    dockerfile = done.stdout
    # the repository's folder is a build argument (--target-repo-dir sets it to /srv/course),
    # and the course, postBuild and the start script all live there, not in ${HOME}
    assert re.search(r"^ARG REPO_DIR=", dockerfile, re.M) and \
        re.search(r"^ENV REPO_DIR=\$\{REPO_DIR\}$", dockerfile, re.M), dockerfile[:3000]
    assert "COPY --chown=1000:1000 src/ ${REPO_DIR}/" in dockerfile
    assert 'ENV R2D_ENTRYPOINT="${REPO_DIR}/start"' in dockerfile

    # postBuild, run with a stand-in pip (nothing is installed), in both layouts
    fake = tmp_path / "bin"
    fake.mkdir()
    (fake / "pip").write_text("#!/bin/sh\necho \"$@\" >> \"$PIP_LOG\"\n")
    (fake / "pip").chmod(0o755)
    for layout in ("hub", "binder"):
        course = tmp_path / layout / "course"
        shutil.copytree(ROOT / "course_lib", course / "course_lib",
                        ignore=shutil.ignore_patterns("__pycache__"))
        shutil.copy2(ROOT / "postBuild", course / "postBuild")
        home = course if layout == "binder" else tmp_path / layout / "home"
        home.mkdir(exist_ok=True)
        env = {**os.environ, "HOME": str(home), "PIP_LOG": str(tmp_path / f"{layout}.pip"),
               "PATH": f"{fake}{os.pathsep}{BIN}{os.pathsep}{os.environ['PATH']}"}
        subprocess.run(["./postBuild"], cwd=course, env=env, check=True, timeout=300)
        assert (tmp_path / f"{layout}.pip").read_text().split() == [
            "install", "--no-deps", "-e", "."]
        writable = [p for p in [course, *course.rglob("*")] if os.stat(p).st_mode & 0o222]
        if layout == "hub":
            assert not writable, f"the hub image's course is writable: {writable[:5]}"
            assert list((course / "course_lib").rglob("*.pyc")), "no bytecode compiled"
        else:
            assert course in writable, "Binder's home (the repository) became read-only"
        for p in [course, *course.rglob("*")]:        # let pytest clean up
            p.chmod(p.stat().st_mode | 0o200)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _naming(text):
    """The pids of the processes whose command line contains `text` (as `pgrep -f`)."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit() and int(entry.name) != os.getpid():
            try:
                if text in (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode(
                        errors="replace"):
                    found.append(int(entry.name))
            except OSError:                      # ended meanwhile, or not ours to read
                pass
    return found


def _course_files():
    """sha256 of every file of the installed course (course_lib and the notebooks)."""
    files = [p for folder in ("course_lib", "notebooks", "exercises", "solutions")
             for p in sorted((ROOT / folder).rglob("*"))
             if p.is_file() and "__pycache__" not in p.parts]
    return {str(p.relative_to(ROOT)): hashlib.sha256(p.read_bytes()).hexdigest() for p in files}


def _rss_mib(pid):
    """Resident memory (MiB) of process `pid` alone, and of it with all its descendants."""
    alone, total, todo = None, 0, [pid]
    while todo:
        p = todo.pop()
        try:
            status = Path(f"/proc/{p}/status").read_text()
            rss = int(re.search(r"VmRSS:\s+(\d+)", status).group(1)) / 1024
            for task in Path(f"/proc/{p}/task").iterdir():
                todo += [int(c) for c in (task / "children").read_text().split()]
        except (FileNotFoundError, ProcessLookupError, AttributeError):
            continue
        alone = rss if p == pid else alone
        total += rss
    return alone, total


class Hub:
    """A JupyterHub started in `folder` with the course's settings; stopped by `stop()`."""

    def __init__(self, folder):
        self.folder = folder
        self.port, self.hub_port, self.api_port = free_port(), free_port(), free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        self.token = secrets.token_hex(16)
        self.homes = folder / "homes"
        self.process = None
        self.values = yaml.safe_load((ROOT / "hub" / "values.yaml").read_text())["hub"]
        self.instructor = self.values["config"]["Authenticator"]["admin_users"][0]
        self.users = [*STUDENTS, self.instructor]

    def config(self, proxy):
        values = self.values
        lines = ["c = get_config()  # noqa"]
        for section, settings in values["config"].items():          # hub.config, as z2jh does
            for key, value in settings.items():
                lines.append(f"c.{section}.{key} = {value!r}")
        lines += [
            # the test's own: loopback ports, this password, local processes, one home each
            "c.JupyterHub.ip = '127.0.0.1'",
            f"c.JupyterHub.port = {self.port}",
            "c.JupyterHub.hub_ip = '127.0.0.1'",
            f"c.JupyterHub.hub_port = {self.hub_port}",
            f"c.ConfigurableHTTPProxy.api_url = 'http://127.0.0.1:{self.api_port}'",
            f"c.ConfigurableHTTPProxy.command = [{str(proxy)!r}]",
            f"c.JupyterHub.db_url = 'sqlite:///{self.folder / 'jupyterhub.sqlite'}'",
            f"c.JupyterHub.cookie_secret_file = {str(self.folder / 'cookie_secret')!r}",
            "c.JupyterHub.authenticator_class = 'shared-password'",
            f"c.SharedPasswordAuthenticator.user_password = {PASSWORD!r}",
            f"c.SharedPasswordAuthenticator.admin_password = {ADMIN_PASSWORD!r}",
            f"c.Authenticator.allowed_users = {set(self.users)!r}",
            "c.JupyterHub.spawner_class = 'simple'",
            f"c.SimpleLocalProcessSpawner.home_dir_template = {str(self.homes) + '/{username}'!r}",
            f"c.Spawner.cmd = [{str(BIN / 'jupyterhub-singleuser')!r}]",
            # Jupyter refuses to serve as root unless told (CI runs as root)
            f"c.Spawner.args = {['--allow-root'] if os.getuid() == 0 else []!r}",
            "c.Spawner.start_timeout = 180",
            "c.Spawner.http_timeout = 180",
            "c.Spawner.environment = {'PYDEVD_DISABLE_FILE_VALIDATION': '1'}",
            "c.JupyterHub.services = [{'name': 'course-test', 'api_token': %r}]" % self.token,
            "c.JupyterHub.load_roles = [{'name': 'course-test', 'services': ['course-test'], "
            "'scopes': ['admin:users', 'admin:servers', 'tokens', 'read:groups', "
            "'access:servers']}]",
        ]
        for name, code in values["extraConfig"].items():          # hub.extraConfig, as it is
            lines += [f"# hub.extraConfig.{name} of hub/values.yaml", code]
        path = self.folder / "jupyterhub_config.py"
        path.write_text("\n".join(lines) + "\n")
        return path

    def start(self):
        npm = subprocess.run([sys.executable, str(ROOT / "scripts" / "npm-ci"),
                              str(ROOT / "hub"), str(ROOT / "build" / "hub-npm")],
                             check=True, stdout=subprocess.PIPE, text=True)
        proxy = Path(npm.stdout.strip()) / ".bin" / "configurable-http-proxy"
        config = self.config(proxy)
        env = {k: v for k, v in os.environ.items()
               if not k.startswith(("JUPYTER", "COURSE_", "XDG_", "IPYTHON", "MPLCONFIG"))}
        env["PATH"] = f"{BIN}{os.pathsep}{env.get('PATH', '')}"
        self.log = open(self.folder / "jupyterhub.log", "w")
        started = time.monotonic()
        self.process = subprocess.Popen([str(BIN / "jupyterhub"), "-f", str(config)],
                                        cwd=self.folder, env=env, stdout=self.log,
                                        stderr=subprocess.STDOUT, start_new_session=True)
        while time.monotonic() - started < 90:
            assert self.process.poll() is None, f"the hub exited:\n{self.log_text()}"
            try:
                if requests.get(f"{self.url}/hub/api/", timeout=2).status_code == 200:
                    break
            except requests.ConnectionError:
                pass
            time.sleep(0.2)
        else:
            raise AssertionError(f"the hub did not answer in 90 s:\n{self.log_text()}")
        self.startup_seconds = time.monotonic() - started
        return self

    def log_text(self):
        return (self.folder / "jupyterhub.log").read_text()[-4000:]

    def api(self, method, path, **kwargs):
        response = requests.request(method, f"{self.url}/hub/api{path}", timeout=60,
                                    headers={"Authorization": f"token {self.token}"}, **kwargs)
        response.raise_for_status()
        return response.json() if response.content else None

    def stop(self):
        """Stop every server, then the hub and its proxy; the pids that were running."""
        pids = set()
        for user in self.api("GET", "/users"):
            if user["servers"]:
                pids.add(self.server_pid(user["name"]))
                requests.delete(f"{self.url}/hub/api/users/{user['name']}/server", timeout=60,
                                headers={"Authorization": f"token {self.token}"})
        pids.add(self.process.pid)
        self.process.send_signal(signal.SIGTERM)
        self.process.wait(timeout=60)
        self.log.close()
        return pids - {None}

    def server_pid(self, name):
        state = self.api("GET", f"/users/{name}", params={"include_stopped_servers": "0"})
        server = state["servers"].get("")
        return (server or {}).get("state", {}).get("pid") if server else None


class Student:
    """One account: a browser session (cookies) and, for the kernel, a token of their own."""

    def __init__(self, hub, name, password=PASSWORD):
        self.hub, self.name = hub, name
        self.session = requests.Session()
        page = self.session.get(f"{hub.url}/hub/login", timeout=60)
        xsrf = self.session.cookies.get("_xsrf") or re.search(
            r'name="_xsrf" value="([^"]+)"', page.text).group(1)
        self.login = self.session.post(f"{hub.url}/hub/login?next=", timeout=60,
                                       data={"username": name, "password": password,
                                             "_xsrf": xsrf}, allow_redirects=False)

    def start_server(self):
        self.session.get(f"{self.hub.url}/hub/spawn", timeout=180)
        deadline = time.monotonic() + 180
        while time.monotonic() < deadline:
            server = self.hub.api("GET", f"/users/{self.name}")["servers"].get("")
            if server and server["ready"]:
                break
            if not server or not server["pending"]:          # the spawn failed
                raise AssertionError(f"{self.name}'s server did not start:\n"
                                     f"{self.hub.log_text()}")
            time.sleep(0.5)
        else:
            raise AssertionError(f"{self.name}'s server did not start:\n{self.hub.log_text()}")
        self.token = self.hub.api("POST", f"/users/{self.name}/tokens",
                                  json={"note": "course test"})["token"]
        self.base = f"{self.hub.url}/user/{self.name}"
        self.home = self.hub.homes / self.name

    def server(self, method, path, **kwargs):
        response = requests.request(method, f"{self.base}{path}", timeout=120, headers={
            "Authorization": f"token {self.token}"}, **kwargs)
        response.raise_for_status()
        return response

    def pull_course(self, repo, branch):
        """nbgitpuller's API, as the link of hub/README.md triggers it: clone into the home."""
        response = self.server("GET", "/git-pull/api", stream=True, params={
            "repo": repo, "branch": branch, "targetpath": COURSE})
        events = [json.loads(line[5:]) for line in response.iter_lines(decode_unicode=True)
                  if line and line.startswith("data:")]
        assert events and events[-1].get("phase") == "finished", events[-3:]

    def kernel(self, notebook, attempts=3):
        """A kernel for `notebook` (a path under the home), as JupyterLab opens one, once it
        answers. Kernels started at the same moment on one machine (these servers', and other
        tests') can draw the same free TCP port, and the second dies at start-up ("Address
        already in use"); JupyterLab would show it restarting. Here it is started again."""
        for attempt in range(attempts):
            session = self.server("POST", "/api/sessions", json={
                "path": notebook, "name": Path(notebook).name, "type": "notebook",
                "kernel": {"name": "python3"}}).json()
            try:
                kernel = Kernel(self, session["kernel"]["id"])
                kernel.run("pass")
                return kernel
            except (websocket.WebSocketException, OSError) as error:
                self.server("DELETE", f"/api/sessions/{session['id']}")
                if attempt == attempts - 1:
                    raise AssertionError(f"{self.name}'s kernel for {notebook} died at "
                                         f"start-up {attempts} times: {error}")
                time.sleep(2)


class Kernel:
    """Run code in a kernel of a student's server over its websocket (the Jupyter protocol)."""

    def __init__(self, student, kernel_id):
        url = student.base.replace("http://", "ws://") + f"/api/kernels/{kernel_id}/channels"
        self.ws = websocket.create_connection(
            url, header=[f"Authorization: token {student.token}"], timeout=300)
        self.session = uuid.uuid4().hex

    def run(self, code):
        """The text the code printed or displayed (Markdown preferred); raises on an error."""
        msg_id = uuid.uuid4().hex
        self.ws.send(json.dumps({
            "header": {"msg_id": msg_id, "username": "test", "session": self.session,
                       "msg_type": "execute_request", "version": "5.3"},
            "parent_header": {}, "metadata": {}, "channel": "shell", "buffers": [],
            "content": {"code": code, "silent": False, "store_history": False,
                        "user_expressions": {}, "allow_stdin": False, "stop_on_error": True}}))
        out, idle, replied = [], False, False
        while not (idle and replied):
            frame = self.ws.recv()
            if isinstance(frame, bytes):              # a binary frame: a widget's buffers
                continue
            msg = json.loads(frame)
            if msg.get("parent_header", {}).get("msg_id") != msg_id:
                continue
            kind, content = msg["msg_type"], msg["content"]
            if kind == "stream":
                out.append(content["text"])
            elif kind in ("execute_result", "display_data"):
                data = content.get("data", {})
                out.append(data.get("text/markdown") or data.get("text/plain", ""))
            elif kind == "error":
                raise AssertionError(f"{content['ename']}: {content['evalue']}\n"
                                     + "\n".join(content["traceback"])[-2000:])
            elif kind == "status" and content["execution_state"] == "idle":
                idle = True
            elif kind == "execute_reply":
                replied = True
        return "".join(out)

    def close(self):
        self.ws.close()


def _code_cells(path):
    return [c["source"] if isinstance(c["source"], str) else "".join(c["source"])
            for c in json.loads(path.read_text())["cells"] if c["cell_type"] == "code"]


def _a_students_session(hub, name, repo, branch):
    """Everything one account does in class; what the test checks afterwards."""
    student = Student(hub, name, ADMIN_PASSWORD if name == hub.instructor else PASSWORD)
    assert student.login.status_code == 302, (name, student.login.status_code)
    student.start_server()
    student.pull_course(repo, branch)
    start_page = f"{COURSE}/notebooks/00_start_here.ipynb"
    page = student.session.get(f"{student.base}/lab/tree/{start_page}", timeout=120)
    assert page.status_code == 200 and "JupyterLab" in page.text, (name, page.status_code)
    result = {"student": student}
    if name in STUDENTS:
        lesson = student.kernel(f"{COURSE}/notebooks/{LESSON}.ipynb")
        started = time.monotonic()
        for code in _code_cells(student.home / COURSE / "notebooks" / f"{LESSON}.ipynb"):
            lesson.run(code)
        result["lesson_seconds"] = time.monotonic() - started
        result["server_pid"] = hub.server_pid(name)
        result["server_mib"] = _rss_mib(result["server_pid"])
        result["probe"] = json.loads(lesson.run(PROBE).strip().splitlines()[-1])
        result["exam"] = json.loads(lesson.run(RECORD_EXAM.format(
            seed=11, chapters=STUDENTS[name])).strip().splitlines()[-1])
        lesson.close()
        start = student.kernel(start_page)
        shown = [start.run(code) for code in
                 _code_cells(student.home / COURSE / "notebooks" / "00_start_here.ipynb")]
        result["progress_shown"] = next(text for text in shown if "mock exam" in text)
        start.close()
    else:
        probe = student.kernel(start_page)
        result["probe"] = json.loads(probe.run(PROBE).strip().splitlines()[-1])
        probe.close()
    return result


@pytest.fixture(scope="module")
def classroom(tmp_path_factory):
    folder = tmp_path_factory.mktemp("hub")
    # the course as nbgitpuller fetches it: a git repository with this checkout's commit
    repo = folder / "course.git"
    subprocess.run(["git", "init", "-q", "--bare", str(repo)], check=True)
    subprocess.run(["git", "-C", str(ROOT), "push", "-q", str(repo), "HEAD:refs/heads/course"],
                   check=True, capture_output=True)
    before = _course_files()
    hub = Hub(folder).start()
    try:
        with concurrent.futures.ThreadPoolExecutor(len(hub.users)) as pool:
            sessions = dict(zip(hub.users, pool.map(
                lambda name: _a_students_session(hub, name, f"file://{repo}", "course"),
                hub.users)))
        yield {"hub": hub, "sessions": sessions, "before": before}
    finally:
        if hub.process.poll() is None:
            try:
                hub.pids = hub.stop()
            except Exception:
                os.killpg(hub.process.pid, signal.SIGKILL)
                raise


def test_each_student_works_in_their_own_home_with_the_installed_course(classroom):
    hub, sessions = classroom["hub"], classroom["sessions"]
    for name in hub.users:
        probe = sessions[name]["probe"]
        home = hub.homes / name
        assert Path(probe["home"]) == home, probe
        assert Path(probe["cwd"]) == home / COURSE / "notebooks", probe
        # the installed course_lib, not a copy pulled into the home
        assert not Path(probe["module"]).is_relative_to(home), probe
        assert (home / COURSE / "notebooks" / f"{LESSON}.ipynb").is_file()


def test_each_students_progress_is_their_own_and_complete(classroom):
    hub, sessions = classroom["hub"], classroom["sessions"]
    for name, chapters in STUDENTS.items():
        result = sessions[name]
        progress = hub.homes / name / ".local" / "share" / "graphics-course" / "progress.json"
        assert Path(result["exam"]["file"]) == progress and progress.is_file(), result["exam"]
        header, *exams = [json.loads(line) for line in progress.read_text().splitlines()]
        assert header["format"] == "graphics-course-progress"
        assert len(exams) == 1, f"{name}'s progress holds {len(exams)} exams, not their 1"
        assert sorted(exams[0]["score"]) == sorted(str(c) for c in chapters), exams[0]
        assert sorted(set(result["exam"]["chapters"])) == chapters
        shown = result["progress_shown"]
        assert shown.startswith("**1 mock exam taken**"), shown[:300]
        for chapter in chapters:
            assert re.search(rf"^\| {chapter} \|", shown, re.M), (name, chapter, shown[:600])
        others = {c for other, cs in STUDENTS.items() if other != name for c in cs}
        assert not any(re.search(rf"^\| {c} \| \d", shown, re.M) for c in others), shown[:600]
    instructor = hub.homes / hub.instructor / ".local" / "share" / "graphics-course"
    assert not (instructor / "progress.json").exists(), "the instructor took no exam"


def test_lecture_mode_is_the_instructors_only(classroom):
    hub, sessions = classroom["hub"], classroom["sessions"]
    assert sessions[hub.instructor]["probe"]["lecture"] == pytest.approx(1.5)
    for name in STUDENTS:
        assert sessions[name]["probe"]["lecture"] == 1.0, (name, sessions[name]["probe"])


def test_a_students_server_refuses_another_students_token_and_cookies(classroom):
    sessions = classroom["sessions"]
    ada, grace = sessions["ada"]["student"], sessions["grace"]["student"]
    mine = requests.get(f"{ada.base}/api/contents/{COURSE}", timeout=60,
                        headers={"Authorization": f"token {ada.token}"})
    assert mine.status_code == 200
    theirs = requests.get(f"{ada.base}/api/contents/{COURSE}", timeout=60,
                          headers={"Authorization": f"token {grace.token}"})
    assert theirs.status_code == 403, theirs.status_code
    # grace's browser, logged in to the hub, asks for ada's server: the hub says no
    with_cookies = grace.session.get(f"{ada.base}/api/contents/{COURSE}", timeout=60)
    assert with_cookies.status_code == 403, (with_cookies.status_code, with_cookies.url)
    assert ada.session.get(f"{ada.base}/api/contents/{COURSE}", timeout=60).status_code == 200


def test_the_hub_refuses_a_wrong_password(classroom):
    hub = classroom["hub"]
    wrong = Student(hub, "ada", password=PASSWORD + "x")
    assert wrong.login.status_code == 403, wrong.login.status_code
    assert "jupyterhub-session-id" not in wrong.session.cookies or \
        wrong.session.get(f"{hub.url}/hub/api/user", timeout=60).status_code == 403


def test_the_installed_course_is_unchanged(classroom):
    after = _course_files()
    before = classroom["before"]
    changed = sorted(k for k in before.keys() | after.keys() if before.get(k) != after.get(k))
    assert not changed, f"the students' work changed the installed course: {changed[:10]}"


def test_zz_everything_stops_cleanly_and_the_figures(classroom):
    hub, sessions = classroom["hub"], classroom["sessions"]
    memory = {name: (*sessions[name]["server_mib"], sessions[name]["probe"]["peak_mib"])
              for name in STUDENTS}
    assert len({sessions[name]["server_pid"] for name in STUDENTS}) == len(STUDENTS)
    hub_alone = _rss_mib(hub.process.pid)[0]
    pids = hub.stop()
    assert hub.process.returncode is not None

    def running():
        """The hub's processes still alive: the hub, the servers, and anything (a kernel, the
        proxy) whose command line names the hub's folder."""
        alive = []
        for p in pids:
            try:
                if "zombie" not in Path(f"/proc/{p}/status").read_text():
                    alive.append(p)
            except OSError:                      # gone
                pass
        return alive + [p for p in _naming(str(hub.folder)) if p not in alive]

    deadline = time.monotonic() + 60          # servers shut their kernels down as they stop
    while running() and time.monotonic() < deadline:
        time.sleep(0.5)
    left = {}
    for p in running():
        try:
            left[p] = Path(f"/proc/{p}/cmdline").read_text().replace("\0", " ")[:200]
        except OSError:                          # it ended in between
            pass
    assert not left, f"still running a minute after the hub stopped: {left}"
    print(f"\nhub start-up: {hub.startup_seconds:.1f} s, the hub process {hub_alone:.0f} MiB; "
          f"per student after {LESSON} ran, "
          "resident MiB of the server alone / the server with its kernel, kernel peak MiB: "
          + ", ".join(f"{n}: {server:.0f} / {total:.0f}, {peak:.0f}"
                      for n, (server, total, peak) in memory.items())
          + "; lesson run: " + ", ".join(f"{n} {sessions[n]['lesson_seconds']:.1f} s"
                                        for n in STUDENTS))
