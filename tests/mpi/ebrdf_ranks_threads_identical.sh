#!/usr/bin/env bash
# eBRDF prefiltering is bitwise identical over ranks and threads (1x1, 1x2, 2x1, 2x2); the result holds the
# normal map and every mip level of both components with sane values; a PNG and a TGA normal map are read
# (the stored normals, written back as pictures, read again to within 8-bit rounding); a picture that is
# not square is refused naming it.
source "$(dirname "$0")/lib/common.bash"
MPI_FLAGS+=(--bind-to none)

cp "$PBRFIT_SOURCE_DIR/tests/jobs/small-ebrdf.yaml" job.yaml
note "reference on 1 rank x 1 thread"
run_ranks 1 run job.yaml --output ref.h5 --threads 1 -q
expect_status 0
for layout in "1 2" "2 1" "2 2"; do
  set -- $layout
  note "$1 rank(s) x $2 thread(s)"
  run_ranks "$1" run job.yaml --output "r-$1x$2.h5" --threads "$2" -q
  expect_status 0
  expect_identical ref.h5 "r-$1x$2.h5" /ebrdf
done

"$H5PY_PYTHON" - <<'PY' || fail "the eBRDF tables are wrong"
import h5py, numpy as np
f = h5py.File("ref.h5", "r")
normals = f["ebrdf/normal_map/normal"][...]
assert normals.shape == (16, 16, 3) and normals.dtype == np.float32
assert np.allclose(np.linalg.norm(normals, axis=2), 1, atol=1e-6) and normals[..., 2].min() >= 0.0099
for component, views in (("specular", (4, 8)), ("diffuse", (2, 4))):
    for level in range(1, 5):
        g = f[f"ebrdf/{component}/mip{level}"]
        side = 16 >> level
        m, a, e = g["matrix"][...], g["amplitude"][...], g["error"][...]
        assert m.shape == (side, side) + views + (9,) and m.dtype == np.float32, (component, level, m.shape)
        assert np.all(np.isfinite(m)) and np.all(np.isfinite(e)) and np.all(e >= 0) and e.max() < 0.2
        det = np.linalg.det(m.reshape(-1, 3, 3).astype(np.float64))
        assert np.allclose(np.abs(det), 1, atol=1e-4), "matrices are scaled to |det M| = 1"
        assert np.all((a > 0) & (a <= 1.0001)), (component, level, a.min(), a.max())
        if component == "diffuse":
            assert np.allclose(a, 1), "the Lambert lobe's albedo is 1"
        assert len(g["theta"]) == views[0] and len(g["phi"]) == views[1]
        assert g.attrs["component"] == component and int(g.attrs["level"]) == level
# The footprint of the coarsest level spans the whole map: its lobe points back near the mirror direction
# of a normal view, so M maps z to a direction close to z.
top = f["ebrdf/specular/mip4/matrix"][0, 0, 0, 0].reshape(3, 3).astype(np.float64)
z = top @ np.array([0, 0, 1.0]); z /= np.linalg.norm(z)
assert z[2] > 0.8, z
PY

note "PNG and TGA normal maps: the stored normals, as 8-bit pictures, read back"
"$H5PY_PYTHON" - <<'PY' || fail "could not write the pictures"
import h5py, numpy as np, matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
n = h5py.File("ref.h5", "r")["ebrdf/normal_map/normal"][...]
rgb = np.clip(np.round((n + 1) / 2 * 255), 0, 255).astype(np.uint8)
plt.imsave("map.png", rgb)
header = bytes([0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 16, 0, 16, 0, 24, 0x20])  # uncompressed, top-left origin
open("map.tga", "wb").write(header + rgb[..., ::-1].tobytes())                # BGR
plt.imsave("wide.png", np.zeros((16, 32, 3), np.uint8))
PY
for picture in map.png map.tga; do
  sed -e "s|normal_map: stone|normal_map: $picture|" -e '/^  size:/d' job.yaml >"job-${picture%.*}-${picture#*.}.yaml"
  run_ranks 2 run "job-${picture%.*}-${picture#*.}.yaml" --output "from-${picture#*.}.h5" -q
  expect_status 0
done
"$H5PY_PYTHON" - <<'PY' || fail "the pictures' normals differ from the stored ones"
import h5py, numpy as np
ref = h5py.File("ref.h5", "r")["ebrdf/normal_map/normal"][...]
for name in ("from-png.h5", "from-tga.h5"):
    f = h5py.File(name, "r")
    got = f["ebrdf/normal_map/normal"][...]
    assert np.abs(got - ref).max() < 0.02, (name, np.abs(got - ref).max())
    assert f["ebrdf/normal_map"].attrs["source"] in ("map.png", "map.tga")
PY
for group in /ebrdf/specular /ebrdf/diffuse /ebrdf/normal_map/normal; do expect_identical from-png.h5 from-tga.h5 $group; done

note "a picture that is not square is refused, naming the job key and the file"
sed -e "s|normal_map: stone|normal_map: wide.png|" -e '/^  size:/d' job.yaml >wide.yaml
run_ranks 1 run wide.yaml -q 2>err.txt
expect_status 2
grep -q "wide.yaml:6:15: error: 'normal_map' names wide.png: a normal map must be square with a power-of-two side of at most 512 pixels; this one is 32 x 16" err.txt ||
  { cat err.txt; fail "wrong message for a picture that is not square"; }
echo "PASS"
