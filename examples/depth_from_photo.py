#!/usr/bin/env python3
"""One corridor photo to a depth PNG and a figure.

    PYTHONPATH=PREFIX/lib/python3/dist-packages \\
        python3 examples/depth_from_photo.py photo.jpg out/ --hfov 60 --camera_height 1.0

Writes out/<photo>_depth.png (16-bit millimetres, 0 = no estimate, as corridor_depth writes)
and out/<photo>_figure.png (the photo with the two floor/wall junction lines, and the depth in
metres with a colour bar). Without --camera, the camera is made from --hfov (degrees).
Exit status 0 with depth, 1 when the photo shows no usable corridor, 2 on bad arguments.
"""

import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # Files only, no display.
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import corridor_depth as cd  # noqa: E402


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("photo", help="an image of a corridor")
    parser.add_argument("output_dir", help="where the depth PNG and the figure go")
    camera = parser.add_mutually_exclusive_group()
    camera.add_argument("--camera", help="calibration YAML (ROS camera_info + camera_height)")
    camera.add_argument("--hfov", type=float, default=60.0,
                        help="horizontal field of view, degrees, without --camera (default 60)")
    parser.add_argument("--camera_height", type=float,
                        help="camera height above the floor, m (overrides the calibration's)")
    parser.add_argument("--upright", action="store_true",
                        help="turn the photo as its EXIF orientation says (a phone photo "
                             "without a calibration; a calibration is for the stored pixels)")
    parser.add_argument("--solver", default="joint", help="grid, closed_form, lm or joint")
    parser.add_argument("--max_depth", type=float, default=15.0,
                        help="top of the colour scale, m (default 15)")
    return parser.parse_args()


def draw_junctions(ax, junctions):
    """Each junction from its near end to the vanishing point; its supported part solid."""
    vp = junctions.vanishing_point
    for line, colour in ((junctions.left, "tab:red"), (junctions.right, "tab:cyan")):
        (u0, v0), (u1, v1) = line.near_end, line.far_end
        ax.plot([u1, vp[0]], [v1, vp[1]], "--", color=colour, linewidth=1)
        ax.plot([u0, u1], [v0, v1], "-", color=colour, linewidth=2.5)
    ax.plot(*vp, "o", color="yellow", markersize=5)


def main():
    args = parse_args()
    photo = pathlib.Path(args.photo)
    out_dir = pathlib.Path(args.output_dir)
    try:
        image = cd.read_image(str(photo), upright=args.upright)  # uint8 HxWx3, BGR
        height, width = image.shape[:2]
        camera = (cd.Camera.from_file(args.camera) if args.camera
                  else cd.Camera.from_hfov(args.hfov, width, height))
        if args.camera_height is None and camera.camera_height == 0:
            raise ValueError("--camera_height is required: the camera carries none")
        options = {"solver": args.solver}
        if args.camera_height is not None:
            options["camera_height"] = args.camera_height
        res = cd.recover_depth(image, camera, **options)
    except (ValueError, OSError) as error:
        print(f"depth_from_photo: {error}", file=sys.stderr)
        return 2

    out_dir.mkdir(parents=True, exist_ok=True)
    depth_png = out_dir / f"{photo.stem}_depth.png"
    figure_png = out_dir / f"{photo.stem}_figure.png"
    cd.write_depth_png(str(depth_png), res.depth)

    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8), constrained_layout=True)
    left.imshow(image[:, :, ::-1])  # BGR -> RGB for matplotlib
    if res.junctions.found:
        draw_junctions(left, res.junctions)
    left.set_xlim(0, width - 1)
    left.set_ylim(height - 1, 0)
    left.set_title(photo.name)
    left.axis("off")
    colours = matplotlib.colormaps["turbo"].copy()
    colours.set_bad("0.8")  # No estimate (NaN) shows grey.
    shown = right.imshow(res.depth, cmap=colours, vmin=0, vmax=args.max_depth)
    right.axis("off")
    if res.ok:
        g = res.geometry
        right.set_title(f"depth: width {g.width:.2f} m, yaw {np.degrees(g.yaw):.1f} deg, "
                        f"pitch {np.degrees(g.pitch):.1f} deg, offset {g.offset:+.2f} m")
    else:
        right.set_title(f"no depth: {res.status}", fontsize=8)
    fig.colorbar(shown, ax=right, label="depth (m)")
    fig.savefig(figure_png, dpi=100)
    plt.close(fig)

    coverage = np.isfinite(res.depth).mean()
    print(f"{photo.name}: {res.status}; confidence {res.confidence:.2f}; "
          f"depth on {100 * coverage:.0f}% of the pixels")
    if res.ok:
        print(f"geometry: {res.geometry}")
    print(f"wrote {depth_png} and {figure_png}")
    return 0 if res.ok else 1


if __name__ == "__main__":
    sys.exit(main())
