"""``graphflow studio``: edit a graph in the browser, validate it with the runtime's own compiler, run it live.

A local web server (Starlette on uvicorn, the ``studio`` extra) serving the run report's page in its
studio mode. Safe by default (docs/studio.md): 127.0.0.1 only, a random token on every request and on
the live stream, Host and Origin checked, files only under the served folder, bodies size-limited.
"""
