# The drills page (#/drills): src/ui/pages/drills/. Every visible string of the page except the
# recipe titles, blurbs and argument labels (recipes.ftl) and the kernels' errors (errors.ftl).

drills-lede = Pick a drill, set its values and run it. Each file you download has the same name, columns and numbers as the Python recipe run with the same arguments, and the command lines under the result reproduce it. Nothing leaves this page.

## Form
drills-picker-label = Drill
drills-run = Run
drills-reset = Defaults
drills-file-using-sample = Input: the built-in labeled sample ({ $name }, { $rows } rows).
drills-file-using = Input: { $name } ({ $size }).
drills-file-using-rows = Input: { $name } ({ $size }, { $rows } rows, { $joints } joint columns).
drills-file-missing = This link used the file “{ $name }”. Open it again to run: files never leave your computer, so a link cannot carry them.
drills-file-too-large = “{ $name }” is { $size }: larger than the { $limit } this drill can read. It was not opened.
drills-file-unreadable = “{ $name }” could not be read ({ $reason }).
drills-reading = Reading { $name }…

## Status beside Run
drills-running = Running…
drills-large = A large run: press Run (or Enter) to compute it. The page is busy while it runs; the largest sizes take a few seconds.
drills-invalid = Fix the value marked in red, then run again.
drills-done = Done in { $ms } ms.
drills-failed = The drill stopped with an error; the message says why.
drills-code-failed = The code that runs the drills could not be loaded. Check the connection and press Run again.

## Notices about the link the page was opened with
drills-url-unknown-recipe = This link names a drill that does not exist (“{ $id }”); showing “{ $title }” instead.

## Result
drills-output-title = Result
drills-output-empty = Nothing computed yet. Press Run, or Enter in any field.
drills-stale = The values changed since this result was computed. Press Run (or Enter) to update it; the files and command lines below still belong to each other.
drills-summary-label = Printed by the recipe
drills-file-size = { $rows ->
    [one] { $rows_text } row
   *[other] { $rows_text } rows
}, { $columns } columns, { $size }
drills-preview-label = Preview of { $file }
drills-preview-empty = Header only: this run wrote no data rows.
drills-preview-all = { $rows ->
    [one] The whole file: { $rows_text } row.
   *[other] The whole file: { $rows_text } rows.
}
drills-preview-some = Showing the first { $shown } of { $rows_text } rows; the download has them all.
drills-preview-columns = Showing { $shown } of { $columns } columns.

## Explanation
drills-about-title = What it computes
drills-quirks-title = Quirks of the Python recipe, reproduced on purpose
drills-about-parity = The numbers are computed in your browser by the same Rust code as the bsv command line, written the way Python writes them (shortest round-trip digits), so a plain diff against the Python recipe's CSV is quiet.

drills-about-pendulum-energy = A damped pendulum (a capsule on a hinge) is stepped exactly as MuJoCo steps it, int(duration ÷ timestep) times. Each row holds the angle θ, the angular velocity ω and three energies: ke = ½ m (L ω)², pe = m g (z + L) and total = ke + pe. With damping the total has to go down; the printed drift is max(total) − min(total).

drills-about-ik-workspace = A square grid with a spacing of step_mm covers ±half_mm around the base. For every cell (x, y) the two-link arm is reachable when c2 = (x² + y² − L1² − L2²) / (2 L1 L2) lies between −1 and 1. Reachable cells get the elbow-down solution q2 = acos c2, q1 = atan2(y, x) − atan2(L2 sin q2, L1 + L2 cos q2), and fk_err_mm, the distance between the cell and the forward kinematics of that solution (round-off only). Unreachable cells leave the angles empty.

drills-about-traj-resample = Reads a trajectory with a time column t_s and one column per joint, and linearly interpolates every joint onto the uniform times t0, t0 + dt, … up to the last time (numpy's interp). Without a file the recipe first writes its labeled synthetic sample and resamples that, so you get two files.

drills-about-dh-fk = Forward kinematics of a fixed three-joint demo chain. For each link, the modified Denavit–Hartenberg transform (joint angle θ = q plus the link's offset) is multiplied onto the previous frame, and every frame's origin x, y, z and its roll, pitch, yaw (XYZ fixed angles) are written, the base frame first.

drills-about-jacobian-2r = Sweeps q1 from q1 start to q1 stop (included) in steps of q1 step at a fixed q2. Each row has the tip position, det J = L1 L2 sin q2, Yoshikawa's manipulability w = √det(J Jᵀ) and the singular values σ_min, σ_max of the Jacobian. For a planar 2R arm these depend on q2 only, so they repeat on every row up to rounding: turning the whole arm does not change how well it can move.

drills-about-cubic-path = The cubic q(t) = q0 + a2 t² + a3 t³ with a2 = 3 (q1 − q0) / T² and a3 = −2 (q1 − q0) / T³ moves from q0 to q1 in time T, starting and stopping at rest. It is sampled every dt from 0 to T with its velocity qd and acceleration qdd. The acceleration is not zero at either end: it jumps when the move starts and stops, which is why smoother planners use quintic polynomials.

drills-about-se3-relative = Builds the homogeneous transforms T_A and T_B of two poses (x, y, z and roll, pitch, yaw with R = Rz(yaw) Ry(pitch) Rx(roll)) and writes T_A⁻¹ T_B: where frame B is, and how it is turned, as seen from frame A.

drills-about-rrt-2d = Grows a rapidly-exploring random tree in the unit square from (0.1, 0.1) towards the goal, around the box obstacle [0.35, 0.65] × [0.25, 0.75]. Each iteration draws a point with numpy's default_rng(seed) (the goal itself one time in ten), steps 0.05 from the nearest node towards it, and keeps the step if it stays in the square and clear of the box. It stops when a node is within 0.06 of the goal. rrt_path.csv is the path from start to goal; rrt_nodes.csv is the whole tree with parent ids.

drills-about-pid-step = A discrete PID controller closes the loop around a first-order plant, y ← y + a (u − y) with a = dt / (τ + dt), dt = 0.05 s, and a unit step setpoint r = 1. Each step computes the error e = r − y, its running sum and its change, the command u = Kp e + Ki ∫e + Kd de/dt, and the new output y. The printed final_y shows how close the loop gets: more Ki removes the remaining error, more Kp makes it overshoot. Gains that make the loop unstable grow the numbers until they print as inf and then nan, exactly as Python prints them.

drills-about-manip-grid = Evaluates det J = L1 L2 sin q2 of the planar 2R arm on an n × n grid of joint angles, q1 and q2 each from −π to π, and prints the largest |det J| and where it is. The arm is most agile with the elbow at a right angle and singular (det J = 0) when it is stretched out or folded back.

drills-about-trapezoid-profile = A move over |distance| that accelerates at amax, cruises at vmax and decelerates at amax (a triangle when vmax is never reached), sampled every dt: time t, position s, velocity v and acceleration a.

drills-about-umeyama-2d = Draws n random points X with numpy's default_rng(seed), makes Y = 1.3 R(35°) X + (0.4, −0.2) plus Gaussian noise of standard deviation σ, and recovers the scale, the rotation angle and the translation with Umeyama's closed form (an SVD of the 2 × 2 cross-covariance). The CSV puts the estimates beside the true values; with σ = 0 the fit is exact up to rounding.

## Keys
drills-key-run = Run the drill
drills-key-enter = Run (while typing in a field)
drills-key-download = Download the first CSV of the result
drills-key-switch = Previous / next drill

## Result: warnings and the table switch
drills-table-exact = Exact values, as in the CSV file
drills-table-rounded = Numbers are rounded to 6 significant digits; the download has every digit.
drills-warnings-title = Check this result
