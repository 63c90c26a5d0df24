"""The figure of a wpg run dataset (`wpg plot`, analysis/plot_run.py), one module per part.

- styles: the colours and markers every panel shares;
- reading: the run groups read from the file, every dataset checked (wpg_file_reading);
- scenario_text: what the stored scenario says (command, obstacles, pushes);
- geometry: sole rectangles, grown outlines, convex hulls;
- top_view: footsteps, CoM and CoP paths, obstacles, the goal and the routes;
- time_panels: CoM and CoP against time, the NMPC solve time and status;
- fig6: the paper's Fig. 6 analogue (multibody ZMP before and after the dynamic filter);
- figure: the panels laid out per run, and the PNG written atomically;
- plan_reading, plan_figure: `--plan`, what the NMPC previewed (mpc/plan/) against what the
  robot did, and the prediction error against the look-ahead.

The modules import numpy and matplotlib at their top: plot_run.py checks that they can be
imported (one line and exit 2 otherwise) before it imports this package.
"""
