"""A page for headless Chromium's screenshot of the desktop in the browser (desktop_test.sh).

Serves, on 127.0.0.1:PORT, a page that shows URL in a full-window frame and loads one resource
that answers after SECONDS of real time. Chromium's virtual time (--virtual-time-budget) does not
wait for a WebSocket, only for pending requests: without the held request the screenshot can be
taken before noVNC has spoken to the VNC server at all (it says "Connecting..."), as it was with
Debian 13's noVNC 1.6. With it, the frame has SECONDS of real time to connect and draw.

    python3 hold_page.py PORT URL SECONDS
"""
import http.server
import sys
import time

PORT, URL, SECONDS = int(sys.argv[1]), sys.argv[2], float(sys.argv[3])
PAGE = (
    '<html><body style="margin:0"><iframe src="%s" style="border:0;width:100vw;height:100vh">'
    '</iframe><img src="/hold" style="display:none"></body></html>' % URL
).encode()


class Handler(http.server.BaseHTTPRequestHandler):
    def do_GET(self):
        body, kind = PAGE, "text/html"
        if self.path.startswith("/hold"):
            time.sleep(SECONDS)
            body, kind = b"", "text/plain"
        self.send_response(200)
        self.send_header("Content-Type", kind)
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, *args):
        pass


http.server.ThreadingHTTPServer(("127.0.0.1", PORT), Handler).serve_forever()
