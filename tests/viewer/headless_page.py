"""Opening the pages of `wpg view` in Debian's headless Chromium, driven over the DevTools
protocol on a pipe (--remote-debugging-pipe: no port, no third-party module), with the network
off (--proxy-server=127.0.0.1:9 fails any request that would leave the machine).

    with HeadlessChromium() as browser:
        page = browser.open("file:///.../run.html#t=6")
        page.wait_for("document.body.dataset.wpgReady === '1'")
        page.screenshot("t6.png")
        page.problems()      # console errors and warnings, exceptions, requests not file://

Everything the page logs is collected with its level (Runtime.consoleAPICalled,
Runtime.exceptionThrown, Log.entryAdded), and every request it makes (Network.requestWillBeSent).
"""
import base64
import json
import os
import select
import shutil
import subprocess
import tempfile
import time

CHROMIUM_FLAGS = [
    "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
    "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-extensions",
    "--disable-default-apps", "--mute-audio", "--proxy-server=127.0.0.1:9",
    # WebGL on the CPU (SwiftShader) without the deprecation warning of the automatic fallback
    "--enable-unsafe-swiftshader",
]

# Messages of Chromium itself, not of the page: its software GL driver's performance notes.
IGNORED_LOG = ("GL Driver Message", "GPU stall due to ReadPixels")


class PageError(Exception):
    pass


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class HeadlessChromium:
    def __init__(self, width=1280, height=800):
        self.width, self.height = width, height
        self.profile = tempfile.mkdtemp(prefix="wpg-chromium-")
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()

        def child():  # the pipe on the file descriptors 3 (commands in) and 4 (answers out)
            a, b = os.dup(to_chrome_r), os.dup(from_chrome_w)
            os.dup2(a, 3)
            os.dup2(b, 4)

        binary = find_chromium()
        if not binary:
            raise PageError("no chromium (the Debian package chromium)")
        self.process = subprocess.Popen(
            [binary, *CHROMIUM_FLAGS, "--remote-debugging-pipe", "--user-data-dir=" + self.profile,
             "--window-size=%d,%d" % (width, height), "about:blank"],
            preexec_fn=child, close_fds=False, stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL)
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        try:
            self.call("Browser.close", timeout=10)
        except Exception:  # noqa: BLE001 - closing anyway
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        for fd in (self.to_chrome, self.from_chrome):
            try:
                os.close(fd)
            except OSError:
                pass
        shutil.rmtree(self.profile, ignore_errors=True)

    def send(self, method, params=None, session=None):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.to_chrome, json.dumps(message).encode() + b"\0")
        return self.next_id

    def receive(self, timeout):
        end = time.monotonic() + timeout
        while b"\0" not in self.buffer:
            left = end - time.monotonic()
            if left <= 0:
                raise PageError("Chromium did not answer within %.0f s" % timeout)
            ready, _, _ = select.select([self.from_chrome], [], [], left)
            if ready:
                chunk = os.read(self.from_chrome, 1 << 20)
                if not chunk:
                    raise PageError("Chromium closed the pipe (exit status %s)" % self.process.poll())
                self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, session=None, timeout=60):
        wanted = self.send(method, params, session)
        while True:
            message = self.receive(timeout)
            if message.get("id") == wanted:
                if "error" in message:
                    raise PageError("%s: %s" % (method, message["error"]))
                return message.get("result", {})
            self.events.append(message)

    def open(self, url):
        target = self.call("Target.createTarget", {"url": "about:blank"})
        session = self.call("Target.attachToTarget",
                            {"targetId": target["targetId"], "flatten": True})["sessionId"]
        page = Page(self, session)
        for domain in ("Runtime", "Page", "Network", "Log"):
            self.call(domain + ".enable", session=session)
        self.call("Emulation.setDeviceMetricsOverride",
                  {"width": self.width, "height": self.height, "deviceScaleFactor": 1,
                   "mobile": False}, session=session)
        self.call("Page.navigate", {"url": url}, session=session)
        return page


class Page:
    def __init__(self, browser, session):
        self.browser, self.session = browser, session

    def evaluate(self, expression, timeout=60):
        result = self.browser.call("Runtime.evaluate",
                                   {"expression": expression, "awaitPromise": True,
                                    "returnByValue": True}, session=self.session, timeout=timeout)
        if "exceptionDetails" in result:
            raise PageError("%s: %s" % (expression, result["exceptionDetails"].get("text")))
        return result.get("result", {}).get("value")

    def wait_for(self, condition, timeout=60):
        """Polls the JavaScript `condition` until it is true."""
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if self.evaluate("Boolean(%s)" % condition):
                return
            time.sleep(0.1)
        raise PageError("not true within %.0f s: %s" % (timeout, condition))

    def screenshot(self, path):
        data = self.browser.call("Page.captureScreenshot", {"format": "png"},
                                 session=self.session)["data"]
        with open(path, "wb") as stream:
            stream.write(base64.b64decode(data))

    def events(self):
        return [e for e in self.browser.events if e.get("sessionId") == self.session]

    def console(self):
        """[(level, text)] of everything the page logged, exceptions as ('exception', text)."""
        lines = []
        for event in self.events():
            method, params = event.get("method"), event.get("params", {})
            if method == "Runtime.consoleAPICalled":
                text = " ".join(str(a.get("value", a.get("description", ""))) for a in params["args"])
                lines.append((params["type"], text))
            elif method == "Runtime.exceptionThrown":
                details = params["exceptionDetails"]
                text = details.get("exception", {}).get("description") or details.get("text")
                lines.append(("exception", text))
            elif method == "Log.entryAdded":
                entry = params["entry"]
                if not any(ignored in entry["text"] for ignored in IGNORED_LOG):
                    lines.append((entry["level"], "[%s] %s" % (entry["source"], entry["text"])))
        return lines

    def requests(self):
        return [e["params"]["request"]["url"] for e in self.events()
                if e.get("method") == "Network.requestWillBeSent"]

    def problems(self, allowed_prefix):
        """Console errors and warnings, exceptions, and requests outside `allowed_prefix` (a
        file:// folder): what a page that works offline must not have."""
        found = ["%s: %s" % (level, text) for level, text in self.console()
                 if level in ("error", "warning", "exception", "assert")]
        found += ["request: " + url for url in self.requests()
                  if not url.startswith(allowed_prefix) and not url.startswith("data:")]
        return found
