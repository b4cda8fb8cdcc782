# The Planar 2R IK page (#/ik-2r): src/ui/pages/ik2r/. Every visible string of the page.

ik2r-lede = Drag the orange tip and both joints follow by inverse kinematics; drag a link to turn one joint. Every number on this page moves with the arm.

## Arm view
ik2r-canvas-label = Arm view: a two-link arm on a millimetre grid. Drag the tip or a link; arrow keys also move the tip.
ik2r-elbow-legend = IK branch
ik2r-elbow-down = Elbow-down (q2 ≥ 0)
ik2r-elbow-up = Elbow-up (q2 < 0)
ik2r-ws-show = Show workspace grid
ik2r-ws-color = Colour cells by
ik2r-ws-color-reach = reachable or not
ik2r-ws-color-manip = manipulability |det J|
ik2r-ws-color-err = FK error (log scale)
ik2r-reset = Reset
ik2r-clamped = Out of reach: the tip stops at the nearest point the arm can reach.
ik2r-drag-hint = Drag the orange tip (inverse kinematics), the elbow or link 1 (turns q1 only) or link 2 (turns q2 only). Keys: arrows move the tip, [ ] turn q1, - = turn q2, e flips the elbow, r resets, w shows the grid.
ik2r-view-notes = Shaded ring: the reachable workspace, { $inner } mm ≤ r ≤ { $outer } mm. Orange ellipse: the tip velocities that unit joint speed can produce, drawn at { $scale }× scale, its axes along the singular directions (solid: σ_max, dashed: σ_min).
ik2r-ws-summary = Workspace grid { $nx } × { $ny } = { $cells } cells, { $reachable } reachable (elbow-down IK in each cell).

## Readouts
ik2r-readouts-title = Live numbers
ik2r-ro-q1 = Joint 1, q1
ik2r-ro-q2 = Joint 2, q2
ik2r-ro-tip = Tip x, y
ik2r-ro-det = det J
ik2r-ro-w = Manipulability w
ik2r-ro-sigma = Singular values σ_min, σ_max
ik2r-ro-jac = Jacobian J =
ik2r-ro-hint = w = √det(J Jᵀ) is Yoshikawa's manipulability; for this arm it equals |det J| = L1 L2 |sin q2|.
ik2r-unit-rad = rad
ik2r-unit-deg = °
ik2r-unit-mm = mm
ik2r-unit-m = m
ik2r-unit-m2 = m²
ik2r-unit-m-per-rad = m/rad
ik2r-unit-cells = cells
ik2r-strip-q1 = q1
ik2r-strip-q2 = q2
ik2r-strip-x = x
ik2r-strip-y = y
ik2r-strip-w = w
ik2r-live-summary = Arm at q1 { $q1 }°, q2 { $q2 }°; tip at x { $x } mm, y { $y } mm; manipulability { $w } m².

## The second stage (heatmap, sweep plot, parameters, downloads)
ik2r-more-loading = Loading the heatmap, the sweep plot, the parameters and the downloads… The arm already works.
ik2r-more-failed = The heatmap, the sweep plot, the parameters and the downloads could not be loaded: the network is not reachable. The arm and its numbers still work. Check the connection, then try again.

## Heatmap
ik2r-heatmap-title = Manipulability over joint space
ik2r-heatmap-label = Heatmap of |det J| over q1 and q2 from −π to π, with the current pose marked. Arrow keys move the marker.
ik2r-heatmap-hint = Colour: |det J| for every pair (q1, q2); the white circle is the current pose. Point at a cell to preview its pose as a grey ghost arm; click or tap to jump there. Red dashed lines: the singular poses q2 = 0 (stretched) and q2 = ±π (folded).
ik2r-heatmap-axis-q1 = q1 [rad]
ik2r-heatmap-axis-q2 = q2 [rad]
ik2r-heatmap-legend = |det J| [m²]
ik2r-heatmap-singular = singular (q2 = 0)
ik2r-heatmap-hover = Preview: q1 = { $q1 } rad, q2 = { $q2 } rad, |det J| = { $det } m²

## Plots
ik2r-plot-title = Jacobian sweep (the jacobian-2r recipe)
ik2r-plot-label = Plots of det J and w (top) and of σ_min and σ_max (bottom) against q1, with the current q1 marked.
ik2r-plot-hint = The recipe's sweep: q1 from start to stop at the arm's current q2. For a planar 2R arm these numbers depend on q2 only, so the lines are flat; turn q2 (drag link 2, or keys - and =) and watch them move together. Orange line: the current q1.
ik2r-plot-x = q1 [rad]
ik2r-plot-top = det J, w [m²]
ik2r-plot-bottom = σ [m]
ik2r-plot-det = det J
ik2r-plot-w = w
ik2r-plot-smin = σ_min
ik2r-plot-smax = σ_max

## Parameters
ik2r-params-title = Parameters
ik2r-params-hint = Changes apply as you type. A value that is not valid is marked beside its field, and the last valid value stays in use.
ik2r-group-arm = Arm
ik2r-group-ws = Workspace grid (ik-workspace)
ik2r-group-sweep = Jacobian sweep (jacobian-2r)
ik2r-group-sweep-note = The sweep is taken at the arm's current q2.
ik2r-group-maps = Manipulability maps
ik2r-field-L1 = Link 1 length L1
ik2r-field-L2 = Link 2 length L2
ik2r-field-half_mm = Half-extent
ik2r-field-step_mm = Step
ik2r-field-q1_start = q1 start
ik2r-field-q1_stop = q1 stop
ik2r-field-q1_step = q1 step
ik2r-field-res = Heatmap resolution
ik2r-hint-res = Cells per axis of the heatmap, 64 to 1,024. Only changes the picture.
ik2r-field-n = manip-grid n

## Downloads
ik2r-downloads-title = Downloads
ik2r-downloads-hint = Each CSV is byte for byte what the recipe writes when run with the command below and the current parameters.
ik2r-dl-ik = Download ik_workspace.csv
ik2r-dl-jac = Download jacobian_2r.csv
ik2r-dl-manip = Download manip_ellipse.csv
ik2r-dl-png = Download the arm view (PNG)
ik2r-dl-png-hint = A picture of the arm view as it is now, at screen resolution.
ik2r-dl-missing-file = the { $recipe } recipe wrote no file named { $file }.

## Shortcuts (the ? overlay)
ik2r-key-nudge = Move the tip 1 mm (with Shift: 10 mm)
ik2r-key-heatmap = On the focused heatmap: move the pose marker (← → q1, ↓ ↑ q2, 0.01 rad; with Shift: 0.1 rad)
ik2r-key-q1 = Turn q1 by 0.01 rad (with Shift: 0.1 rad)
ik2r-key-q2 = Turn q2 by 0.01 rad (with Shift: 0.1 rad)
ik2r-key-elbow = Flip the elbow (the other IK solution)
ik2r-key-reset = Reset everything to the defaults
ik2r-key-workspace = Show or hide the workspace grid

## Explanation panel
ik2r-explain-title = What the page shows
ik2r-ex-branches-title = Two answers to one question
ik2r-ex-branches = Inverse kinematics asks: which joint angles put the tip here? For a two-link arm, almost every reachable point has two answers, mirror images of each other across the line from the base to the tip. The recipes take q2 = +acos(c2), the branch this page calls elbow-down; elbow-up is q2 = −acos(c2).
ik2r-ex-branches-2 = Press e or use the switch: the tip stays where it is while q2 changes sign. On the edges of the ring the two answers merge into one, and outside the ring there is none, because c2 = (x² + y² − L1² − L2²) / (2 L1 L2) leaves the range −1 to 1.
ik2r-ex-jacobian-title = The Jacobian
ik2r-ex-jacobian = The Jacobian J turns joint speeds into tip speed: (ẋ, ẏ) = J (q̇1, q̇2). Each column is the tip velocity you get by turning one joint at 1 rad/s with the other held still, so its entries are in metres per radian. Watch the columns change as you drag.
ik2r-ex-w-title = Manipulability
ik2r-ex-w = Yoshikawa's manipulability w = √det(J Jᵀ) says how freely the tip can move in every direction at once. For a square J it is |det J|, and for this arm |det J| = L1 L2 |sin q2|: largest with the elbow at a right angle, zero when the arm is straight or folded.
ik2r-ex-ellipse = The orange ellipse shows every tip velocity that unit joint speed can produce. Its long semi-axis σ_max is the easy direction, its short one σ_min the hard direction; σ_min × σ_max = w.
ik2r-ex-sing-title = Singularities
ik2r-ex-sing = At q2 = 0 (stretched out) and q2 = ±π (folded back) the links line up, det J = 0 and σ_min = 0: the tip cannot move along the arm at all, however fast the joints turn, and IK close to such a pose asks for huge joint speeds. On the heatmap they are the dashed lines; in the arm view they are the edges of the ring.
ik2r-ex-flat-title = Why the sweep lines are flat
ik2r-ex-flat = Turning the whole arm about its base does not change its shape, so det J, w and the singular values depend on q2 alone. The jacobian-2r recipe sweeps q1 at a fixed q2, so every row has the same numbers (up to rounding). The heatmap shows the same fact as horizontal bands.

## The recipes behind the page (as on the BSV page)
ik2r-recipes-title = The recipes behind this page
ik2r-recipes-hint = The page computes these three BSV recipes in your browser; the downloads above are their CSVs.
ik2r-rc-input = Input
ik2r-rc-output = Output
ik2r-rc-prereq = Prerequisites
ik2r-rc-steps = Steps
ik2r-rc-expected = Expected result
ik2r-rc-ik-title = Sample a planar 2-link IK workspace
ik2r-rc-ik-summary = Grid the plane, mark reachable cells, and record elbow-down IK plus FK error in millimeters.
ik2r-rc-ik-input = L1, L2 (m), half-extent mm, step mm (defaults 0.12 0.10 200 10).
ik2r-rc-ik-output = ik_workspace.csv with reachable flag and joint angles.
ik2r-rc-ik-prereq = Python 3 + numpy.
ik2r-rc-ik-step1 = Save the script.
ik2r-rc-ik-step2 = Run: python planar_ik_workspace.py 0.12 0.10 200 10
ik2r-rc-ik-step3 = Filter reachable=1 before plotting.
ik2r-rc-ik-expected = A rectangular grid CSV. Outside the annulus reachable=0.
ik2r-rc-ik-note = On this page: “Show workspace grid” draws this grid under the arm.
ik2r-rc-jac-title = Planar 2R Jacobian and manipulability sweep
ik2r-rc-jac-summary = Sweep q1 with fixed q2, write det(J), Yoshikawa manipulability and singular values. Simulation literacy only.
ik2r-rc-jac-input = L1,L2 m; q1 start/stop/step; q2 (defaults 0.12 0.10 0 1.57 0.1 0.8).
ik2r-rc-jac-output = jacobian_2r.csv.
ik2r-rc-jac-prereq = Python 3 + numpy.
ik2r-rc-jac-step1 = Save the script.
ik2r-rc-jac-step2 = Run: python jacobian_planar_2r.py
ik2r-rc-jac-step3 = Watch manipulability drop near singularities.
ik2r-rc-jac-expected = Tens of rows; min manipulability near singular postures is small.
ik2r-rc-jac-note = On this page: the sweep plots; the CSV uses the arm's current q2 instead of the default 0.8.
ik2r-rc-manip-title = Planar 2R manipulability grid
ik2r-rc-manip-summary = Sample |det J| over a joint grid. Pairs with the IK Field Lab.
ik2r-rc-manip-input = L1 L2 n (defaults 0.12 0.10 24).
ik2r-rc-manip-output = manip_ellipse.csv.
ik2r-rc-manip-prereq = Python 3 stdlib.
ik2r-rc-manip-step1 = Save the script.
ik2r-rc-manip-step2 = Run: python manip_ellipse_2r.py
ik2r-rc-manip-step3 = Find max manip.
ik2r-rc-manip-expected = n² rows; near-zero manip near singularities.
ik2r-rc-manip-note = On this page: the heatmap samples the same grid at its own resolution; the CSV uses the field “manip-grid n”. Despite its name the file holds |det J| only, no ellipse.

ik2r-safety = Research, education and simulation only. Nothing here is a safety-rated controller or an authority for real hardware.
