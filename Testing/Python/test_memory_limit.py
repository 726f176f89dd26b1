"""Host memory running out while a mapper prepares a mesh: the mapper gives one error and draws
nothing, with no crash, and draws the mesh once memory is there again. The failure is forced: each
mapper renders a small mesh, then, in a process whose address space is capped a little above what it
uses (RLIMIT_AS), a mesh of 1.3 million tetrahedra, then the same mesh with the cap lifted. Each mapper
runs in a child process of its own, so that a crash is reported as one. The mesh is large enough that
memory runs out in the mapper's own preparation: with a smaller one, Mesa's llvmpipe may be the one
to run out first, compiling a program or allocating a buffer, where it aborts the process (LLVM) or
keeps a program it could not compile."""
import json
import os
import resource
import subprocess
import sys
import unittest

MAPPERS = ("tetrahedra", "shells", "hexahedral")
HEADROOM = 20 * 2**20  # above the address space in use: too little for the large mesh's preparation


def address_space():
    with open("/proc/self/status") as status:
        return int(next(line for line in status if line.startswith("VmSize")).split()[1]) * 1024


def child(name):
    """Renders as the module's description says; prints the three frames' alpha ranges and counts."""
    from fixtures import Scene, analytic, camera_for, property_from_nodes
    import unstructuredvolume as uv
    mapper = {"tetrahedra": uv.vtkPreIntegratedTetrahedraMapper, "shells": uv.vtkBarycentricShellMapper,
              "hexahedral": uv.vtkHexahedralRayCastMapper}[name]()
    small, large = analytic(3), analytic(60)
    prop = property_from_nodes(((0, 0.0), (1, 0.5)), ((0, (1, 0, 0)), (1, (0, 0, 1))), 0.5)
    scene = Scene(small, prop, camera_for(small), 64, mapper=mapper)
    frames = [scene.render().GetPointData().GetScalars().GetRange(3)]
    scene.mapper.SetInputData(large)
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    resource.setrlimit(resource.RLIMIT_AS, (address_space() + HEADROOM, hard))
    try:
        frames.append(scene.render().GetPointData().GetScalars().GetRange(3))
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))
    errors_when_limited = scene.events.errors
    frames.append(scene.render().GetPointData().GetScalars().GetRange(3))
    print(json.dumps({"frames": frames, "limited_errors": errors_when_limited, "errors": scene.events.errors}))


class MemoryLimitTests(unittest.TestCase):
    def run_child(self, name):
        result = subprocess.run([sys.executable, os.path.abspath(__file__), name], capture_output=True, text=True,
                                timeout=300)
        self.assertEqual(result.returncode, 0, result.stderr[-2000:])
        return json.loads(result.stdout.strip().splitlines()[-1])

    def test_one_error_and_nothing_drawn_then_drawn_again(self):
        for name in MAPPERS:
            with self.subTest(mapper=name):
                report = self.run_child(name)
                small, limited, again = report["frames"]
                self.assertGreater(small[1], 0.05)
                self.assertEqual(limited, [0.0, 0.0])
                self.assertEqual(report["limited_errors"], 1)
                self.assertGreater(again[1], 0.05)
                self.assertEqual(report["errors"], 1)


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] in MAPPERS:
        child(sys.argv[1])
    else:
        unittest.main()
