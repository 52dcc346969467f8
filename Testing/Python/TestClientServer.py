"""pvpython test of a client-server session: starts a local pvserver, connects, loads the
plugin on the server, runs the filter there and fetches its outputs.

    pvpython TestClientServer.py PLUGIN"""
import os
import socket
import subprocess
import sys
import time

from paraview import servermanager
from paraview.simple import Connect, Disconnect, LoadPlugin, Wavelet


def free_port():
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def main(plugin):
    port = free_port()
    server = subprocess.Popen(["pvserver", "--server-port=%d" % port],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        deadline = time.time() + 60
        for line in server.stdout:  # wait until the server listens
            if "Accepting connection" in line or time.time() > deadline:
                break
        Connect("localhost", port)
        LoadPlugin(plugin, remote=True, ns=globals())
        image = Wavelet(WholeExtent=[-32, 31, -32, 31, 0, 0])
        cvt = CVTImage(Input=image, Density=["POINTS", "RTData"], NumberOfSites=40,
                       MaximumNumberOfIterations=20)
        cvt.UpdatePipeline()
        sites = servermanager.Fetch(cvt, idx=0)
        count = sites.GetNumberOfPoints()
        energy = sites.GetFieldData().GetArray("Energy").GetValue(0)
        Disconnect()
        ok = count == 40 and energy > 0
        print("client-server: %d sites, energy %g: %s" % (count, energy, "ok" if ok else "FAILED"))
        return 0 if ok else 1
    finally:
        try:
            server.wait(timeout=5)  # pvserver exits when its client disconnects
        except subprocess.TimeoutExpired:
            server.terminate()
            server.wait(timeout=30)


sys.exit(main(sys.argv[1]))
