#!/usr/bin/python3
"""Corrupt input files through `cvt`: every format it reads (PNG, JPEG, VTI, MHA, VTP, VTK, STL,
PLY, OBJ, CSV sites), each cut at random lengths, with random bit flips, and as a valid header
followed by random bytes, plus wrong extensions and a few bytes of text under every image and
mesh extension. Seeded, bounded. Every case must end in a clean exit (0 when the damage was
harmless, or an error whose every stderr line starts with "cvt:"), never a signal, never a hang;
the few bytes of text must be refused. Prints the outcome counts.
Usage: corrupt_files.py PATH/TO/cvt PNG [CASES_PER_FORMAT]"""
import os
import random
import subprocess
import sys
import tempfile

import vtk


def sources(folder, png):
    """One valid file per format, made here from the bundled density image and a disk mesh."""
    made = {'png': png}
    image = vtk.vtkPNGReader()
    image.SetFileName(png)
    for writer, ext in [(vtk.vtkJPEGWriter, 'jpg'), (vtk.vtkXMLImageDataWriter, 'vti'),
                        (vtk.vtkMetaImageWriter, 'mha')]:
        w = writer()
        w.SetInputConnection(image.GetOutputPort())
        w.SetFileName(os.path.join(folder, 'source.' + ext))
        w.Write()
        made[ext] = w.GetFileName()
    disk = vtk.vtkDiskSource()
    disk.SetInnerRadius(0.0)
    disk.SetCircumferentialResolution(40)
    disk.SetRadialResolution(8)
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(disk.GetOutputPort())
    for writer, ext in [(vtk.vtkXMLPolyDataWriter, 'vtp'), (vtk.vtkPolyDataWriter, 'vtk'),
                        (vtk.vtkSTLWriter, 'stl'), (vtk.vtkPLYWriter, 'ply'), (vtk.vtkOBJWriter, 'obj')]:
        w = writer()
        w.SetInputConnection(triangles.GetOutputPort())
        w.SetFileName(os.path.join(folder, 'source.' + ext))
        if hasattr(w, 'SetFileTypeToBinary'):
            w.SetFileTypeToBinary()
        w.Write()
        made[ext] = w.GetFileName()
    csv = os.path.join(folder, 'source.csv')
    with open(csv, 'w') as out:
        for i in range(20):
            out.write(f'{-0.9 + 0.09 * i},{0.5 - 0.05 * i}\n')
    made['csv'] = csv
    return made


def damage(data, case, rng):
    mode = case % 3
    if mode == 0:
        return data[:rng.randint(0, max(0, len(data) - 1))]
    if mode == 1:
        out = bytearray(data)
        for _ in range(rng.randint(1, 30)):
            i = rng.randrange(len(out))
            out[i] ^= 1 << rng.randrange(8)
        return bytes(out)
    return data[:16] + bytes(rng.getrandbits(8) for _ in range(rng.randint(1, 4000)))


def main():
    cvt, png = sys.argv[1], sys.argv[2]
    cases = int(sys.argv[3]) if len(sys.argv) > 3 else 20
    rng = random.Random(2026)
    counts = {'accepted': 0, 'clean error': 0, 'noisy error': 0, 'wrongly accepted': 0, 'crash': 0, 'hang': 0}
    bad = []
    with tempfile.TemporaryDirectory() as folder:
        made = sources(folder, png)
        runs = []
        for ext, path in made.items():
            data = open(path, 'rb').read()
            for case in range(cases):
                name = os.path.join(folder, f'{ext}{case}.{ext}')
                with open(name, 'wb') as out:
                    out.write(damage(data, case, rng))
                runs.append((ext, name))
        # Wrong extensions: a mesh named .png, a picture named .stl, a CSV named .vtp.
        for wrong, right in [('png', 'stl'), ('stl', 'png'), ('vtp', 'csv'), ('jpg', 'vti')]:
            name = os.path.join(folder, f'wrong.{wrong}')
            with open(name, 'wb') as out:
                out.write(open(made[right], 'rb').read())
            runs.append((wrong, name))
        # Not a file of the format at all: refused (VTK's PNG reader reads this as a 1 x 1 image).
        refuse = set()
        for ext in made:
            if ext != 'csv':
                name = os.path.join(folder, f'text.{ext}')
                with open(name, 'w') as out:
                    out.write('garbage')
                runs.append((ext, name))
                refuse.add(name)
        for ext, name in runs:
            if ext == 'csv':
                command = [cvt, 'image', '--resolution', '32', '--initial-sites', name]
            elif ext in ('png', 'jpg', 'vti', 'mha'):
                command = [cvt, 'image', '--input', name, '--sites', '20']
            else:
                command = [cvt, 'surface', '--input', name, '--sites', '20']
            command += ['--iterations', '2', '--quiet', '--output', os.path.join(folder, 'out')]
            environment = dict(os.environ, DISPLAY='')
            try:
                run = subprocess.run(command, capture_output=True, timeout=120, env=environment)
            except subprocess.TimeoutExpired:
                counts['hang'] += 1
                bad.append(('hang', name))
                continue
            lines = run.stderr.decode(errors='replace').splitlines()
            if run.returncode == 0 and name not in refuse:
                counts['accepted'] += 1
            elif run.returncode == 0:
                counts['wrongly accepted'] += 1
                bad.append(('accepted, should be refused', name))
            elif run.returncode > 0 and lines and all(line.startswith('cvt: ') for line in lines):
                counts['clean error'] += 1
            elif run.returncode > 0 and any(line.startswith('cvt: ') for line in lines):
                counts['noisy error'] += 1
                bad.append(('lines other than cvt: ...', name, run.stderr[-300:]))
            else:
                counts['crash'] += 1
                bad.append((f'exit {run.returncode}', name, run.stderr[-200:]))
    total = sum(counts.values())
    print(f'{total} corrupt files: ' + ', '.join(f'{k} {v}' for k, v in counts.items()))
    for b in bad:
        print('  ', *b)
    print('corrupt files: ' + ('ok' if not bad else 'FAILED'))
    sys.exit(1 if bad else 0)


main()
