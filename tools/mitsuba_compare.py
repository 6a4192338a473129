#!/usr/bin/env python3
"""Independent check of slc's glTF metallic-roughness path tracing against
Mitsuba 3 (https://mitsuba.readthedocs.io), block by block.

The scene: a room (Lambertian floor and walls, open top), six spheres of
glTF materials (roughness 0.05, 0.2, 0.5 perceptual; metallic 0 and 1),
a quad area light and a small sphere light (or, with --point-light, a point
light: its caustics through the near-mirror spheres are found only by a
BSDF sample that the sphere's next-event estimate connects, with weights up
to 1/(pi alpha^2), and need about 1.7M spp for 3% blocks). This script writes the geometry as
flat-shaded OBJ files and the materials, lights and camera twice: as an slc
scene file (`[[geometry]] obj = ..., material = {...}`) and as a Mitsuba
scene dictionary. Mitsuba renders it with its own `path` integrator (MIS,
Russian roulette), emitters, sensor, box filter and GGX visible-normal
sampler; only the BRDF *formula* is restated here, as a Mitsuba BSDF plugin
written from the glTF 2.0 specification (Appendix B: Lambert diffuse
weighted by 1 - F, GGX D from Mitsuba's `MicrofacetDistribution`,
height-correlated Smith G2 = 1/(1 + Lambda_i + Lambda_o) from Mitsuba's G1,
Schlick Fresnel, the metal/dielectric mix), because Mitsuba's own
`roughconductor`/`roughplastic` use the separable Smith G and other Fresnel
and diffuse terms, which slc does not model.

Both renderers run several independent seeds; the comparison takes each
4x4 block's mean and its standard error from the spread of the seeds, and
reports the image mean and the worst block as relative differences with
their noise. Targets (issue 30): image mean within 1 %, worst 4x4 block
within 3 %, for slc's CPU and GPU backends.

    pip install mitsuba numpy
    cargo build --release -p slc-cli
    python3 tools/mitsuba_compare.py [--spp 1024] [--seeds 4] [--size 64] [--backends cpu,gpu] [--point-light] [--out DIR]

Issue 30's rows (docs/results/mitsuba-sphere-light.md): --spp 1024 --mitsuba-spp 4096 --seeds 16 --method slc
(16 seeds per renderer, so that each block's standard error is itself
well estimated).

Mitsuba's llvm_ad_rgb variant needs libLLVM (Mesa's lavapipe brings it);
--variant scalar_rgb works without it, far slower.
"""

import argparse
import json
import math
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MAX_DEPTH = 8  # slc's default: surface vertices after the camera


def icosphere(levels):
    t = (1.0 + 5 ** 0.5) / 2.0
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7),
         (9, 8, 1)]
    norm = lambda p: tuple(c / math.sqrt(sum(x * x for x in p)) for c in p)
    tris = [tuple(norm(v[i]) for i in face) for face in f]
    for _ in range(levels):
        out = []
        for a, b, c in tris:
            ab, bc, ca = (norm(tuple((x + y) / 2 for x, y in zip(p, q))) for p, q in ((a, b), (b, c), (c, a)))
            out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        tris = out
    return tris


def quad(a, b, c, d):
    return [(a, b, c), (a, c, d)]


def write_obj(path, tris):
    with open(path, "w") as f:
        for t in tris:
            for p in t:
                f.write("v %.7f %.7f %.7f\n" % p)
        for i in range(len(tris)):
            f.write("f %d %d %d\n" % (3 * i + 1, 3 * i + 2, 3 * i + 3))


def scene(out, point_light):
    """Writes the OBJs; returns (objects, lights, camera). With `point_light`
    the second light is a point light; otherwise a small sphere of emissive
    triangles at the same position, of about the same intensity."""
    s = 1.5
    objects = [
        ("floor", quad((-s, 0, s), (s, 0, s), (s, 0, -s), (-s, 0, -s)), dict(base=(0.5, 0.5, 0.5), lambert=True)),
        ("back", quad((-s, 0, -s), (s, 0, -s), (s, 2, -s), (-s, 2, -s)), dict(base=(0.55, 0.55, 0.6), lambert=True)),
        ("left", quad((-s, 0, s), (-s, 0, -s), (-s, 2, -s), (-s, 2, s)), dict(base=(0.6, 0.12, 0.1), lambert=True)),
        ("right", quad((s, 0, -s), (s, 0, s), (s, 2, s), (s, 2, -s)), dict(base=(0.12, 0.5, 0.15), lambert=True)),
    ]
    ball = icosphere(3)
    for i, rough in enumerate((0.05, 0.2, 0.5)):
        for j, metal in enumerate((0.0, 1.0)):
            c = (-0.8 + 0.8 * i, 0.3, -0.45 + 0.9 * j)
            tris = [tuple(tuple(0.3 * p[k] + c[k] for k in range(3)) for p in t) for t in ball]
            base = (1.0, 0.78, 0.34) if metal else (0.75, 0.15, 0.12)
            objects.append(("ball-%d-%d" % (i, j), tris, dict(base=base, metallic=metal, roughness=rough)))
    # A large, dim light: the paths a near-mirror sphere reflects onto it
    # from a diffuse surface are found by BSDF sampling alone, in both
    # renderers; a large light makes them less rare and less bright.
    l = 0.6
    light = quad((-l, 1.9, -l), (l, 1.9, -l), (l, 1.9, l), (-l, 1.9, l))  # faces down
    objects.append(("light", light, dict(base=(0.5, 0.5, 0.5), lambert=True, emission=(2.2, 2.0, 1.8))))
    position, intensity = (0.9, 1.1, 1.0), (0.8, 0.7, 0.6)
    lights = []
    if point_light:
        lights.append(dict(position=position, intensity=intensity))
    else:
        # A sphere of radius r and radiance L has the intensity L·π r² in
        # every direction: about the point light's (the 80-triangle sphere
        # inscribed in it shows a little less area), spread over a disc
        # that a near-mirror sphere reflects as a spot, not as a point.
        r = 0.08
        tris = [tuple(tuple(r * p[k] + position[k] for k in range(3)) for p in t) for t in icosphere(1)]
        radiance = tuple(i / (math.pi * r * r) for i in intensity)
        objects.append(("bulb", tris, dict(base=(0.0, 0.0, 0.0), lambert=True, emission=radiance)))
    for name, tris, _ in objects:
        write_obj(os.path.join(out, name + ".obj"), tris)
    camera = dict(position=(0.0, 1.7, 3.9), look_at=(0.0, 0.45, 0.0), fov=40.0)
    return objects, lights, camera


def slc_scene_file(out, objects, lights, camera):
    lines = ["# Written by tools/mitsuba_compare.py", "[camera]",
             "position = %s" % list(camera["position"]), "look_at = %s" % list(camera["look_at"]),
             "fov = %s" % camera["fov"], ""]
    for name, _, m in objects:
        mat = "base_color = %s" % list(m["base"])
        if m.get("lambert"):
            mat += ", specular = 0.0"
        else:
            mat += ", metallic = %s, roughness = %s" % (m["metallic"], m["roughness"])
        if "emission" in m:
            mat += ", emission = %s" % list(m["emission"])
        lines += ["[[geometry]]", 'obj = "%s.obj"' % name, "material = { %s }" % mat, ""]
    for p in lights:
        lines += ["[[light]]", 'type = "point"', "position = %s" % list(p["position"]),
                  "intensity = %s" % list(p["intensity"]), ""]
    path = os.path.join(out, "scene.toml")
    with open(path, "w") as f:
        f.write("\n".join(lines))
    return path


def register_gltf_bsdf(mi, dr):
    """The glTF 2.0 reference BRDF as a Mitsuba BSDF: GGX from Mitsuba's
    MicrofacetDistribution (D, G1, visible-normal sampling), the rest as the
    specification writes it."""

    class Gltf(mi.BSDF):
        def __init__(self, props):
            mi.BSDF.__init__(self, props)
            self.base = mi.Color3f(props["r"], props["g"], props["b"])
            self.metallic = props["metallic"]
            self.alpha = max(props["roughness"] ** 2, 0.001)  # slc_core::brdf::ggx_alpha
            self.f0 = 0.04
            self.distr = mi.MicrofacetDistribution(mi.MicrofacetType.GGX, self.alpha, True)
            flags = mi.BSDFFlags.DiffuseReflection | mi.BSDFFlags.GlossyReflection | mi.BSDFFlags.FrontSide
            self.m_flags = flags
            self.m_components = [mi.BSDFFlags.DiffuseReflection | mi.BSDFFlags.FrontSide,
                                 mi.BSDFFlags.GlossyReflection | mi.BSDFFlags.FrontSide]

        def schlick(self, f0, f90, c):
            x = dr.clip(1.0 - c, 0.0, 1.0)
            return f0 + (f90 - f0) * (x * x * x * x * x)

        def p_spec(self, cos_i):
            # Any lobe choice is unbiased; this mirrors slc's for speed only.
            fd = self.schlick(mi.Color3f(self.f0), 1.0, cos_i)
            fb = self.schlick(self.base, 1.0, cos_i)
            s = dr.mean((1 - self.metallic) * fd + self.metallic * fb)
            d = dr.mean((1 - fd) * self.base * (1 - self.metallic))
            return dr.select(d <= 0, 1.0, dr.clip(s / (s + d), 0.1, 0.9))

        def eval_core(self, wi, wo):
            cos_i, cos_o = mi.Frame3f.cos_theta(wi), mi.Frame3f.cos_theta(wo)
            ok = (cos_i > 0) & (cos_o > 0)
            h = dr.normalize(wi + wo)
            vh = dr.dot(wi, h)
            fd = self.schlick(mi.Color3f(self.f0), 1.0, vh)
            fb = self.schlick(self.base, 1.0, vh)
            fs = (1 - self.metallic) * fd + self.metallic * fb
            lam_i = 1.0 / self.distr.smith_g1(wi, h) - 1.0
            lam_o = 1.0 / self.distr.smith_g1(wo, h) - 1.0
            g2 = 1.0 / (1.0 + lam_i + lam_o)
            spec = fs * self.distr.eval(h) * g2 / (4.0 * cos_i * cos_o)
            diff = (1.0 - fd) * self.base * (1.0 - self.metallic) / math.pi
            return dr.select(ok, (diff + spec) * cos_o, 0.0)

        def pdf_core(self, wi, wo):
            cos_i, cos_o = mi.Frame3f.cos_theta(wi), mi.Frame3f.cos_theta(wo)
            h = dr.normalize(wi + wo)
            p_spec = self.p_spec(cos_i)
            ps = self.distr.pdf(wi, h) / (4.0 * dr.abs(dr.dot(wo, h)))
            pd = dr.maximum(cos_o, 0.0) / math.pi
            return dr.select((cos_i > 0) & (cos_o > 0), p_spec * ps + (1 - p_spec) * pd, 0.0)

        def sample(self, ctx, si, sample1, sample2, active):
            wi = si.wi
            p_spec = self.p_spec(mi.Frame3f.cos_theta(wi))
            spec = sample1 < p_spec
            m, _ = self.distr.sample(wi, sample2)
            wo_s = 2.0 * dr.dot(wi, m) * m - wi
            wo_d = mi.warp.square_to_cosine_hemisphere(sample2)
            wo = dr.select(spec, wo_s, wo_d)
            bs = mi.BSDFSample3f()
            bs.wo = wo
            bs.pdf = self.pdf_core(wi, wo)
            bs.eta = 1.0
            bs.sampled_type = dr.select(spec, mi.UInt32(+mi.BSDFFlags.GlossyReflection), mi.UInt32(+mi.BSDFFlags.DiffuseReflection))
            bs.sampled_component = dr.select(spec, mi.UInt32(1), mi.UInt32(0))
            value = self.eval_core(wi, wo)
            ok = active & (bs.pdf > 0) & (mi.Frame3f.cos_theta(wi) > 0)
            return bs, dr.select(ok, value / bs.pdf, 0.0)

        def eval(self, ctx, si, wo, active):
            return dr.select(active, self.eval_core(si.wi, wo), 0.0)

        def pdf(self, ctx, si, wo, active):
            return dr.select(active, self.pdf_core(si.wi, wo), 0.0)

        def eval_pdf(self, ctx, si, wo, active):
            return self.eval(ctx, si, wo, active), self.pdf(ctx, si, wo, active)

        def traverse(self, callback):
            pass

        def to_string(self):
            return "Gltf[]"

    mi.register_bsdf("gltf", lambda props: Gltf(props))


def mitsuba_render(mi, out, objects, lights, camera, size, spp, seed):
    T = mi.ScalarTransform4f
    d = {"type": "scene", "integrator": {"type": "path", "max_depth": MAX_DEPTH + 1},
         "sensor": {"type": "perspective", "fov": camera["fov"], "fov_axis": "y",
                    "to_world": T().look_at(origin=camera["position"], target=camera["look_at"], up=(0, 1, 0)),
                    "sampler": {"type": "independent", "sample_count": spp, "seed": seed},
                    "film": {"type": "hdrfilm", "width": size, "height": size, "rfilter": {"type": "box"},
                             "pixel_format": "rgb"}}}
    for name, _, m in objects:
        if m.get("lambert"):
            bsdf = {"type": "diffuse", "reflectance": {"type": "rgb", "value": list(m["base"])}}
        else:
            bsdf = {"type": "gltf", "r": m["base"][0], "g": m["base"][1], "b": m["base"][2],
                    "metallic": float(m["metallic"]), "roughness": float(m["roughness"])}
        shape = {"type": "obj", "filename": os.path.join(out, name + ".obj"), "face_normals": True, "bsdf": bsdf}
        if "emission" in m:
            shape["emitter"] = {"type": "area", "radiance": {"type": "rgb", "value": list(m["emission"])}}
        d[name] = shape
    for i, p in enumerate(lights):
        d["point%d" % i] = {"type": "point", "position": list(p["position"]),
                            "intensity": {"type": "rgb", "value": list(p["intensity"])}}
    img = mi.render(mi.load_dict(d), spp=spp, seed=seed)
    return np.array(img, dtype=np.float64)[:, :, :3]


def slc_render(scene_path, backend, size, spp, seed, out, method, error_bound):
    exr = os.path.join(out, "slc-%s-%d.exr" % (backend, seed))
    cmd = [os.path.join(ROOT, "target", "release", "slc"), "render", "--app", "pt", "--backend", backend,
           "--scene", scene_path, "--width", str(size), "--height", str(size), "--spp", str(spp),
           "--method", method, "--seed", str(seed), "--out", exr]
    if error_bound is not None:
        cmd += ["--error-bound", str(error_bound)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    import mitsuba as mi  # its Bitmap reads the EXR
    return np.array(mi.Bitmap(exr), dtype=np.float64)[:, :, :3]


def blocks(img, b=4):
    h, w, _ = img.shape
    return img.reshape(h // b, b, w // b, b, 3).mean(axis=(1, 3)).mean(axis=2)


def compare(name, ours, ref):
    """Relative differences of the image mean and of each 4x4 block (grey),
    with the standard errors from the seeds' spread."""
    n_o, n_r = len(ours), len(ref)
    mo, mr = np.mean(ours, axis=0), np.mean(ref, axis=0)
    im_o = np.array([x.mean() for x in ours])
    im_r = np.array([x.mean() for x in ref])
    se_mean = math.sqrt(im_o.var(ddof=1) / n_o + im_r.var(ddof=1) / n_r)
    mean_rel = (mo.mean() - mr.mean()) / mr.mean()
    print("%-8s own noise of the image mean: slc %.3f%%, Mitsuba %.3f%%" % (
        name, 100 * math.sqrt(im_o.var(ddof=1) / n_o) / mo.mean(), 100 * math.sqrt(im_r.var(ddof=1) / n_r) / mr.mean()))
    bo = np.array([blocks(x) for x in ours])
    br = np.array([blocks(x) for x in ref])
    bmo, bmr = bo.mean(axis=0), br.mean(axis=0)
    se_b = np.sqrt(bo.var(axis=0, ddof=1) / n_o + br.var(axis=0, ddof=1) / n_r)
    lit = bmr > 0.1 * bmr.mean()
    rel = np.where(lit, (bmo - bmr) / np.maximum(bmr, 1e-12), 0.0)
    worst = np.unravel_index(np.argmax(np.abs(rel)), rel.shape)
    res = dict(name=name, image_mean=float(mo.mean()), reference_mean=float(mr.mean()),
               mean_rel=float(mean_rel), mean_rel_sigma=float(se_mean / mr.mean()),
               worst_block=[int(worst[0]), int(worst[1])], worst_block_rel=float(rel[worst]),
               worst_block_rel_sigma=float(se_b[worst] / bmr[worst]),
               blocks_beyond_3pct=int(np.sum(np.abs(rel) > 0.03)), blocks=int(lit.sum()),
               median_block_rel=float(np.median(np.abs(rel[lit]))),
               blocks_beyond_3sigma=int(np.sum(lit & (np.abs(bmo - bmr) > 3 * se_b))))
    print("%-8s image mean %.5f vs Mitsuba %.5f: %+.3f%% (σ %.3f%%); worst 4x4 block %s: %+.2f%% (σ %.2f%%); "
          "median |block| %.2f%%; %d of %d lit blocks beyond 3%%, %d beyond 3σ (their own noise)" % (
              name, res["image_mean"], res["reference_mean"], 100 * mean_rel, 100 * res["mean_rel_sigma"],
              tuple(res["worst_block"]), 100 * res["worst_block_rel"], 100 * res["worst_block_rel_sigma"],
              100 * res["median_block_rel"], res["blocks_beyond_3pct"], res["blocks"], res["blocks_beyond_3sigma"]))
    return res


def pixel(rc, name, ours, ref):
    """One pixel's grey value per seed in both renderers, with the mean and
    its standard error (a highlight smaller than a pixel is found by the
    pixel's samples at random)."""
    r, c = (int(x) for x in rc.split(","))
    for who, imgs in (("Mitsuba", ref), ("slc " + name, ours)):
        v = np.array([x[r, c].mean() for x in imgs])
        print("pixel (%d, %d) %-8s per seed %s: mean %.3f ± %.3f" % (
            r, c, who, np.array2string(v, precision=2), v.mean(), v.std(ddof=1) / math.sqrt(len(v))))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--spp", type=int, default=1024, help="samples per pixel per seed (both renderers)")
    ap.add_argument("--mitsuba-spp", type=int, default=0, help="Mitsuba's samples per pixel per seed [default: 4 × --spp]")
    ap.add_argument("--seeds", type=int, default=4)
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--backends", default="cpu,gpu")
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--method", default="slc-weighted", help="slc's light selection")
    ap.add_argument("--error-bound", type=float, default=None, help="slc's ε [default: slc's own]")
    ap.add_argument("--out", default="target/mitsuba-compare")
    ap.add_argument("--seed-offset", type=int, default=0, help="added to every seed of both renderers (fresh seeds)")
    ap.add_argument("--point-light", action="store_true",
                    help="a point light in place of the small sphere light (its caustics through the near-mirror "
                         "spheres need about 1.7M spp for 3%% blocks)")
    ap.add_argument("--pixel", default=None, help="ROW,COL: also print this pixel's per-seed values and their mean")
    a = ap.parse_args()
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    import mitsuba as mi
    import drjit as dr
    mi.set_variant(a.variant)
    register_gltf_bsdf(mi, dr)
    objects, lights, camera = scene(out, a.point_light)
    path = slc_scene_file(out, objects, lights, camera)
    mspp = a.mitsuba_spp or 4 * a.spp
    ref = [mitsuba_render(mi, out, objects, lights, camera, a.size, mspp, 1000 + a.seed_offset + s) for s in range(a.seeds)]
    mi.Bitmap(np.mean(ref, axis=0).astype(np.float32)).write(os.path.join(out, "mitsuba.exr"))
    results = []
    for backend in a.backends.split(","):
        ours = [slc_render(path, backend, a.size, a.spp, 1 + a.seed_offset + s, out, a.method, a.error_bound)
                for s in range(a.seeds)]
        results.append(compare(backend, ours, ref))
        if a.pixel:
            pixel(a.pixel, backend, ours, ref)
    with open(os.path.join(out, "compare.json"), "w") as f:
        json.dump(dict(size=a.size, spp=a.spp, mitsuba_spp=mspp, seeds=a.seeds, results=results), f, indent=1)
    ok = all(abs(r["mean_rel"]) <= 0.01 and abs(r["worst_block_rel"]) <= 0.03 for r in results)
    print("targets (mean within 1%%, worst block within 3%%): %s" % ("met" if ok else "MISSED"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
