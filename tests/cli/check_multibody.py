"""check_multibody.py RUN.h5 [--filtered | --not-filtered] [--min-reduction R]: the multibody
fields of datasets/SCHEMA.md are there and consistent.

Every group under /runs/ has q (n x nq, `names` = its columns), zmp_multibody (n x 2), the
multibody/ summary attributes and the timing/ profile; with --filtered also com_filtered
(n x 3) and zmp_multibody_filtered (n x 2), and the filter cuts the RMS and the max ZMP error
at least R times (default 3); with --not-filtered neither filtered dataset exists.
"""
import argparse
import sys

import h5py
import numpy as np

SUMMARY = ("zmp_error_rms_before", "zmp_error_max_before", "zmp_error_rms_after",
           "zmp_error_max_after", "ik_failures", "samples_with_limit_violations",
           "violated_joints", "filtered")
TIMING = ("chain_time_average", "chain_time_std", "chain_time_min", "chain_time_max")

errors = []


def check(condition, message):
    if not condition:
        errors.append(message)
    return condition


def described(where, dataset):
    for attr in ("units", "description"):
        check(attr in dataset.attrs, "%s lacks the attribute %s" % (where, attr))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run_file")
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--filtered", action="store_true")
    group.add_argument("--not-filtered", action="store_true")
    parser.add_argument("--min-reduction", type=float, default=3.0)
    parser.add_argument("--min-reduction-max", type=float, default=None,
                        help="for the max error (default: --min-reduction)")
    parser.add_argument("--max-before-end", type=float, default=None, metavar="S",
                        help="compare the filtered max over the samples more than S seconds "
                        "before the walk's end only (a walk to a goal ends with the CoM moving)")
    parser.add_argument("--mode", choices=("online", "offline", "closed_loop"), default=None,
                        help="the filter_mode attribute the file must hold")
    parser.add_argument("--offline-comparison", action="store_true",
                        help="the offline_zmp_error_* attributes of filter_settings.mode both")
    args = parser.parse_args()
    if args.min_reduction_max is None:
        args.min_reduction_max = args.min_reduction
    with h5py.File(args.run_file, "r") as f:
        for name, run in f["runs"].items():
            where = "/runs/%s" % name
            n = run["time"].shape[0]
            if check("q" in run, where + "/q missing"):
                q = run["q"]
                names = [str(v) for v in q.attrs.get("names", [])]
                check(q.ndim == 2 and q.shape[0] == n and q.shape[1] == len(names) > 7,
                      "%s/q shape %s with %d names" % (where, q.shape, len(names)))
                check(names[:7] == ["base_x", "base_y", "base_z", "base_qw", "base_qx", "base_qy",
                                    "base_qz"], "%s/q names start %s" % (where, names[:7]))
                check(np.all(np.isfinite(q[()])), where + "/q not finite")
                described(where + "/q", q)
            if check("zmp_multibody" in run, where + "/zmp_multibody missing"):
                check(run["zmp_multibody"].shape == (n, 2), where + "/zmp_multibody shape")
                described(where + "/zmp_multibody", run["zmp_multibody"])
            filtered_sets = ("com_filtered", "zmp_multibody_filtered")
            if args.filtered:
                for key, columns in zip(filtered_sets, (3, 2)):
                    if check(key in run, "%s/%s missing" % (where, key)):
                        check(run[key].shape == (n, columns), "%s/%s shape" % (where, key))
                        check(np.all(np.isfinite(run[key][()])), "%s/%s not finite" % (where, key))
                        described("%s/%s" % (where, key), run[key])
            if args.not_filtered:
                for key in filtered_sets:
                    check(key not in run, "%s/%s present without the filter" % (where, key))
            if check("multibody" in run, where + "/multibody missing"):
                attrs = run["multibody"].attrs
                for key in SUMMARY:
                    check(key in attrs, "%s/multibody lacks the attribute %s" % (where, key))
                check(attrs.get("ik_failures") == 0, where + ": IK failures")
                if args.filtered:
                    check(attrs.get("filtered") == 1, where + "/multibody: filtered != 1")
                    before, after = attrs["zmp_error_rms_before"], attrs["zmp_error_rms_after"]
                    check(after * args.min_reduction < before,
                          "%s: ZMP error RMS %.4f -> %.4f m, not %gx smaller"
                          % (where, before, after, args.min_reduction))
                    # the attributes agree with the datasets
                    cop = run["cop"][()]
                    error = np.sqrt(np.sum((cop - run["zmp_multibody_filtered"][()]) ** 2, 1))
                    before, after = attrs["zmp_error_max_before"], attrs["zmp_error_max_after"]
                    check(abs(error.max() - after) < 1e-9,
                          "%s: zmp_error_max_after %.6f, the datasets give %.6f"
                          % (where, after, error.max()))
                    span = "max"
                    if args.max_before_end is not None:
                        time = run["time"][()]
                        after = error[time < time[-1] - args.max_before_end].max()
                        span = "max before the last %g s" % args.max_before_end
                    check(after * args.min_reduction_max < before,
                          "%s: ZMP error max %.4f -> %s %.4f m, not %gx smaller"
                          % (where, before, span, after, args.min_reduction_max))
                    rms = np.sqrt(np.mean(error ** 2))
                    check(abs(rms - attrs["zmp_error_rms_after"]) < 1e-9,
                          "%s: zmp_error_rms_after %.6f, the datasets give %.6f"
                          % (where, attrs["zmp_error_rms_after"], rms))
                if args.mode:
                    check(attrs.get("filter_mode") == args.mode,
                          "%s/multibody: filter_mode %r, expected %r"
                          % (where, attrs.get("filter_mode"), args.mode))
                if args.offline_comparison:
                    for key in ("offline_zmp_error_rms_before", "offline_zmp_error_max_before",
                                "offline_zmp_error_rms_after", "offline_zmp_error_max_after"):
                        check(key in attrs and attrs[key] > 0, "%s/multibody lacks %s" % (where, key))
            if check("timing" in run, where + "/timing missing"):
                timing = run["timing"]
                k = run["mpc/time"].shape[0]
                check(timing["chain_time"].shape == (k,), where + "/timing/chain_time shape")
                check(timing["chain_stage_time"].shape == (k, 4),
                      where + "/timing/chain_stage_time shape")
                check(timing["chain_stage_time"].attrs.get("columns")
                      == "nmpc, ik, multibody_zmp, filter", where + "/timing columns")
                for key in TIMING:
                    check(key in timing.attrs, "%s/timing lacks %s" % (where, key))
                chain = timing["chain_time"][()]
                check(np.all(chain > 0), where + "/timing/chain_time not positive")
                check(abs(timing.attrs["chain_time_max"] - chain.max()) < 1e-15,
                      where + "/timing: chain_time_max disagrees")
                # per control period: one row per tick (the closing sample is not one), the
                # NMPC ticks those of the iterations
                if check("tick_stage_time" in timing, where + "/timing/tick_stage_time missing"):
                    ticks = timing["tick_stage_time"]
                    check(ticks.shape == (n - 1, 4), "%s/timing/tick_stage_time shape %s"
                          % (where, ticks.shape))
                    check(ticks.attrs.get("columns") == "wpg, ik, multibody_zmp, filter",
                          where + "/timing/tick_stage_time columns")
                    flags = timing["tick_nmpc"][()]
                    check(flags.shape == (n - 1,) and int(flags.sum()) == k,
                          "%s/timing/tick_nmpc: %d NMPC ticks for %d iterations"
                          % (where, int(flags.sum()), k))
                    check(np.all(ticks[()] >= 0), where + "/timing/tick_stage_time negative")


if __name__ == "__main__":
    try:
        main()
    except (OSError, KeyError) as error:
        errors.append(str(error))
    for error in errors:
        print("check_multibody: %s" % error, file=sys.stderr)
    sys.exit(1 if errors else 0)
