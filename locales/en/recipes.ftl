# The twelve recipes: title, one-line description, and a label for each positional argument
# (`-arg-<name>`) and option (`-flag-<name>`), named as in each module's `INFO`.

## pendulum-energy
recipe-pendulum-energy-title = Log pendulum energy drift in MuJoCo
recipe-pendulum-energy-blurb = Simulate a damped pendulum and write kinetic/potential/total energy vs time. Drift is expected with damping — the point is to see it in a CSV.
recipe-pendulum-energy-arg-duration_s = Duration (s)
recipe-pendulum-energy-flag-damping = Hinge damping b (N·m·s/rad)
recipe-pendulum-energy-flag-angle-deg = Starting angle from hanging straight down (degrees)
recipe-pendulum-energy-flag-timestep = Integrator step h (s)
recipe-pendulum-energy-flag-length = Capsule length L (m)
recipe-pendulum-energy-flag-mass = Capsule mass m (kg)
recipe-pendulum-energy-flag-radius = Capsule radius r (m)
recipe-pendulum-energy-flag-integrator = Integrator: euler (MuJoCo default) or rk4

## ik-workspace
recipe-ik-workspace-title = Sample a planar 2-link IK workspace
recipe-ik-workspace-blurb = Grid the plane, mark reachable cells, and record elbow-down IK plus FK error in millimeters.
recipe-ik-workspace-arg-L1 = Link 1 length L1 (m)
recipe-ik-workspace-arg-L2 = Link 2 length L2 (m)
recipe-ik-workspace-arg-half_mm = Grid half-width (mm)
recipe-ik-workspace-arg-step_mm = Grid step (mm)

## traj-resample
recipe-traj-resample-title = Resample a joint trajectory onto a fixed dt
recipe-traj-resample-blurb = Linearly interpolate q columns onto a uniform time grid. Default input is a labeled synthetic sample.
recipe-traj-resample-arg-csv_path = Trajectory CSV (t_s, q1, q2, …); none = labeled sample
recipe-traj-resample-arg-dt = Time step dt (s)

## dh-fk
recipe-dh-fk-title = Forward kinematics for a short DH chain
recipe-dh-fk-blurb = Apply modified DH transforms for a fixed 3R demo chain and write each frame origin plus XYZ RPY.
recipe-dh-fk-arg-angles = Joint angles q1,q2,q3 (rad, comma-separated)

## jacobian-2r
recipe-jacobian-2r-title = Planar 2R Jacobian and manipulability sweep
recipe-jacobian-2r-blurb = Sweep q1 with fixed q2, write det(J), Yoshikawa manipulability and singular values. Simulation literacy only.
recipe-jacobian-2r-arg-L1 = Link 1 length L1 (m)
recipe-jacobian-2r-arg-L2 = Link 2 length L2 (m)
recipe-jacobian-2r-arg-q1_start = q1 start (rad)
recipe-jacobian-2r-arg-q1_stop = q1 stop, included (rad)
recipe-jacobian-2r-arg-q1_step = q1 step (rad)
recipe-jacobian-2r-arg-q2 = q2, held fixed (rad)

## cubic-path
recipe-cubic-path-title = Cubic joint path with zero end velocities
recipe-cubic-path-blurb = Classic interpolating cubic q(t) from q0 to q1. Not a real-time motion planner.
recipe-cubic-path-arg-q0 = Start angle q0 (rad)
recipe-cubic-path-arg-q1 = End angle q1 (rad)
recipe-cubic-path-arg-T = Duration T (s)
recipe-cubic-path-arg-dt = Time step dt (s)

## se3-relative
recipe-se3-relative-title = Relative SE(3) pose between two XYZ+RPY frames
recipe-se3-relative-blurb = Form T_A and T_B, write T_A⁻¹ T_B as xyz + rpy. Education only.
recipe-se3-relative-arg-ax = Frame A: x (m)
recipe-se3-relative-arg-ay = Frame A: y (m)
recipe-se3-relative-arg-az = Frame A: z (m)
recipe-se3-relative-arg-ar = Frame A: roll (rad)
recipe-se3-relative-arg-ap = Frame A: pitch (rad)
recipe-se3-relative-arg-aw = Frame A: yaw (rad)
recipe-se3-relative-arg-bx = Frame B: x (m)
recipe-se3-relative-arg-by = Frame B: y (m)
recipe-se3-relative-arg-bz = Frame B: z (m)
recipe-se3-relative-arg-br = Frame B: roll (rad)
recipe-se3-relative-arg-bp = Frame B: pitch (rad)
recipe-se3-relative-arg-bw = Frame B: yaw (rad)

## rrt-2d
recipe-rrt-2d-title = Toy 2D RRT around a rectangular obstacle
recipe-rrt-2d-blurb = Grow a small RRT in the unit square from start to goal. Toy planner — not for real robots or safety cases.
recipe-rrt-2d-arg-seed = Random seed
recipe-rrt-2d-arg-max_iter = Maximum iterations
recipe-rrt-2d-flag-obstacle = Obstacle box x0,y0,x1,y1
recipe-rrt-2d-flag-start = Start x,y
recipe-rrt-2d-flag-goal = Goal x,y
recipe-rrt-2d-flag-step = Step length
recipe-rrt-2d-flag-goal-bias = Goal bias
recipe-rrt-2d-flag-goal-tol = Goal tolerance
recipe-rrt-2d-flag-goal-x = Goal x, 0 to 1
recipe-rrt-2d-flag-goal-y = Goal y, 0 to 1

## pid-step
recipe-pid-step-title = Discrete PID step response (toy plant)
recipe-pid-step-blurb = Closed-loop step on a 1st-order plant. Simulation literacy only — not a real controller.
recipe-pid-step-arg-Kp = Proportional gain Kp
recipe-pid-step-arg-Ki = Integral gain Ki (1/s)
recipe-pid-step-arg-Kd = Derivative gain Kd (s)
recipe-pid-step-arg-tau = Plant time constant τ (s)
recipe-pid-step-arg-steps = Number of steps (0.05 s each)

## manip-grid
recipe-manip-grid-title = Planar 2R manipulability grid
recipe-manip-grid-blurb = Sample |det J| over a joint grid.
recipe-manip-grid-arg-L1 = Link 1 length L1 (m)
recipe-manip-grid-arg-L2 = Link 2 length L2 (m)
recipe-manip-grid-arg-n = Grid size n (n × n joint configurations)

## trapezoid-profile
recipe-trapezoid-profile-title = Trapezoidal velocity profile
recipe-trapezoid-profile-blurb = Accel / cruise / decel scalar move. Not a robot driver.
recipe-trapezoid-profile-arg-distance = Move distance
recipe-trapezoid-profile-arg-vmax = Speed limit vmax
recipe-trapezoid-profile-arg-amax = Acceleration limit amax
recipe-trapezoid-profile-arg-dt = Time step dt (s)

## umeyama-2d
recipe-umeyama-2d-title = Umeyama 2D similarity alignment (toy)
recipe-umeyama-2d-blurb = Recover scale/rotation/translation from noisy correspondences.
recipe-umeyama-2d-arg-sigma = Noise standard deviation σ
recipe-umeyama-2d-arg-seed = Random seed
recipe-umeyama-2d-arg-n = Number of point pairs n
recipe-umeyama-2d-flag-scale = True scale s
recipe-umeyama-2d-flag-angle = True angle (°)
recipe-umeyama-2d-flag-tx = True translation tx
recipe-umeyama-2d-flag-ty = True translation ty
recipe-umeyama-2d-flag-mirror = Mirror X first
recipe-umeyama-2d-flag-x = Source points X (x,y;x,y;…)

## Argument hints: the limits of each argument in words (`ArgSpec::hint_id`), the numbers
## as the kernels' constants give them (a test checks they agree).
recipe-pendulum-energy-hint-duration_s = Seconds, more than 0. The run takes whole steps of the time step, from 1 to 1,000,000 steps (up to 2,000 s at the default 0.002 s step).
recipe-pendulum-energy-hint-damping = 0 or more (N·m·s/rad), no upper limit. With 0 the body's real energy stays constant, up to the integrator's error.
recipe-pendulum-energy-hint-angle-deg = Degrees from hanging straight down; any number.
recipe-pendulum-energy-hint-timestep = Seconds, more than 0, no upper limit. Smaller steps mean more rows: at most 1,000,000 steps.
recipe-pendulum-energy-hint-length = Metres, more than 0, no upper limit.
recipe-pendulum-energy-hint-mass = Kilograms, more than 0, no upper limit.
recipe-pendulum-energy-hint-radius = Metres, more than 0, no upper limit.
recipe-pendulum-energy-hint-integrator = euler is MuJoCo's default (semi-implicit, damping implicit), as in the recipe; rk4 is the classic fourth-order Runge–Kutta.
recipe-2r-hint-L1 = Metres, from 0.000001 to 10.
recipe-2r-hint-L2 = Metres, from 0.000001 to 10.
recipe-ik-workspace-hint-half_mm = Millimetres, from 0 to 1,000,000.
recipe-ik-workspace-hint-step_mm = Millimetres, more than 0. The grid may have at most 1,001 × 1,001 cells (for example ±500 mm in 1 mm steps).
recipe-traj-resample-hint-csv_path = A CSV with a t_s column (seconds, always increasing) and one column per joint; a note column is dropped. Up to 128 MiB.
recipe-traj-resample-hint-dt = Seconds, more than 0. The output may have at most 20,000,000 cells (rows × joints).
recipe-dh-fk-hint-angles = Three angles in radians, separated by commas.
recipe-jacobian-2r-hint-q1_start = Radians, from −1,000 to 1,000.
recipe-jacobian-2r-hint-q1_stop = Radians, at least q1 start and at most 1,000.
recipe-jacobian-2r-hint-q1_step = Radians, more than 0. At most 1,000,000 samples.
recipe-jacobian-2r-hint-q2 = Radians, from −1,000 to 1,000.
recipe-cubic-path-hint-q0 = Radians, from −1,000,000,000 to 1,000,000,000.
recipe-cubic-path-hint-q1 = Radians, from −1,000,000,000 to 1,000,000,000.
recipe-cubic-path-hint-T = Seconds, from 0.000000001 to 1,000,000,000.
recipe-cubic-path-hint-dt = Seconds, more than 0. At most 1,000,000 rows (T ÷ dt + 1).
recipe-se3-relative-hint-position = Metres; any number.
recipe-se3-relative-hint-angle = Radians, not degrees; any number.
recipe-hint-seed = A whole number from 0 to 9,223,372,036,854,775,807 (2⁶³ − 1), as numpy's default_rng takes it. The same seed gives the same numbers as Python.
recipe-rrt-2d-hint-max_iter = A whole number from 0 to 1,000,000. The tree stops early when it reaches the goal. A million iterations take about a second.
recipe-rrt-2d-hint-goal-x = From 0 to 1 (the unit square); the same as the x of “goal”. Set this way, a goal inside a box is allowed and never reached.
recipe-rrt-2d-hint-obstacle = Four numbers x0,y0,x1,y1 from 0 to 1 with x0 ≤ x1 and y0 ≤ y1: one box, edges included. Give it once per box, at most 32; the boxes given replace the recipe’s box, and “none” leaves the square empty.
recipe-rrt-2d-hint-start = Two numbers x,y from 0 to 1, outside every box: the root of the tree.
recipe-rrt-2d-hint-goal = Two numbers x,y from 0 to 1, outside every box.
recipe-rrt-2d-hint-step = From 0.001 to 1: the longest extension of one iteration (the recipe’s STEP).
recipe-rrt-2d-hint-goal-bias = From 0 to 1: how often the goal itself is the sample (the recipe’s GOAL_BIAS).
recipe-rrt-2d-hint-goal-tol = From 0.001 to 1.5: a new node nearer than this to the goal, with a clear segment, ends the search (the recipe’s GOAL_TOL).
recipe-rrt-2d-hint-goal-y = From 0 to 1 (the unit square); the same as the y of “goal”. Set this way, a goal inside a box is allowed and never reached.
recipe-pid-step-hint-Kp = Any number (no unit). Too large or negative gains make the loop unstable.
recipe-pid-step-hint-Ki = Any number, per second.
recipe-pid-step-hint-Kd = Any number, in seconds.
recipe-pid-step-hint-tau = Seconds, from 0 to 1,000,000.
recipe-pid-step-hint-steps = A whole number from 0 to 1,000,000 (50,000 s of 0.05 s steps).
recipe-manip-grid-hint-n = A whole number from 1 to 1,024: n × n rows, so at most 1,048,576.
recipe-trapezoid-profile-hint-distance = Any number from −1,000,000,000 to 1,000,000,000; the sign is ignored.
recipe-trapezoid-profile-hint-vmax = Not 0; its size from 0.000000001 to 1,000,000,000. The sign is ignored.
recipe-trapezoid-profile-hint-amax = Not 0; its size from 0.000000001 to 1,000,000,000. The sign is ignored.
recipe-trapezoid-profile-hint-dt = Seconds, more than 0. At most 1,000,000 rows (the move's duration ÷ dt).
recipe-umeyama-2d-hint-sigma = 0 or more, no upper limit (0: no noise, an exact fit).
recipe-umeyama-2d-hint-n = A whole number from 2 to 100,000.
recipe-umeyama-2d-hint-scale = More than 0, at most 1,000 (the recipe’s is 1.3).
recipe-umeyama-2d-hint-angle = From −360 to 360 degrees (the recipe’s is 35).
recipe-umeyama-2d-hint-t = From −1,000 to 1,000 (the recipe’s t is (0.4, −0.2)).
recipe-umeyama-2d-hint-mirror = Choose yes to mirror X (y → −y) before the similarity: no rotation can fit it, and the reflection fix shows.
recipe-umeyama-2d-hint-x = n points as x,y pairs separated by semicolons, each coordinate from −1,000 to 1,000; blank: the recipe’s random points.

## Quirks: what the port decides where the Python recipe is silent, odd or crashes
## (`RecipeInfo::quirks_id`).
recipe-pendulum-energy-quirks = The energies treat the pendulum as a point mass m at the tip, at distance L, not as the capsule that is simulated, so “total” is not the body's real mechanical energy and it changes even without damping. pe uses the tip height from before each step (where MuJoCo last computed positions), and the time column is i·h although the state is the one after step i.
recipe-ik-workspace-quirks = Beyond the recipe: links must be from 0.000001 to 10 m (zero divides by zero in Python) and the grid may have at most 1,001 × 1,001 cells. Cells exactly on the rim of the reachable ring count as reachable, as in Python (|c2| ≤ 1).
recipe-traj-resample-quirks = The note column of the sample (or of your file) is dropped from the output. Time must increase from each row to the next: the Python recipe does not check this and np.interp then returns nonsense without a warning, so this page refuses such a file and names the first row where time does not increase.
recipe-dh-fk-quirks = The chain uses modified (Craig) DH parameters, not the classic (standard) convention: the same four numbers in a classic-DH tool give different frames. The base row is written as literal zeros, and −0.0 appears where the reference computes a negative zero (a pitch of atan2(−0.0, 1)). It equals 0; it is printed as Python prints it.
recipe-jacobian-2r-quirks = q1 stop is included (the recipe adds 1e-12 to it). A stop below the start, or a step of 0, makes the Python recipe crash on an empty sweep; here they are refused with the argument named. At most 1,000,000 samples.
recipe-cubic-path-quirks = T and dt must be more than 0, as the recipe itself checks. The last sample is at the last multiple of dt that does not pass T, so with a dt that does not divide T the path stops short of q1.
recipe-se3-relative-quirks = The Python recipe's description says the angles are in degrees, but its code passes them straight to cos and sin, so they are radians (0.2 rad ≈ 11.5°). Typing 30 meaning 30° gives a turn of 30 rad. Angles are read back from the rotation matrix with pitch between −π/2 and π/2; at pitch ±π/2 (gimbal lock) roll is set to 0.
recipe-rrt-2d-quirks = A segment is checked for collision at only 12 evenly spaced points, so it can cut across a corner of the box. When the goal is not reached within max_iter iterations (try a goal inside the box), rrt_path.csv has only its header and the printed length is nan.
recipe-pid-step-quirks = The setpoint and dt = 0.05 s are fixed in the recipe. A negative step count gives an empty table in Python; here it is refused. An unstable loop (too large or negative gains) grows until it prints inf and then nan, exactly as Python prints it; the page warns when that happens.
recipe-manip-grid-quirks = The Python file is called manip_ellipse_2r.py and writes manip_ellipse.csv, but no ellipse is computed: detJ is det J and manip is |det J|, the area scale of the manipulability ellipse. The Planar 2R IK playground draws the ellipse itself.
recipe-trapezoid-profile-quirks = Time advances by repeated addition, t += dt while t ≤ t_total, so rounding builds up and decides how many rows there are; each row prints round(t, 5). In the triangle case the deceleration keeps d_acc from the vmax that is never reached, so the positions overshoot: with 0.2 1.0 2.0 the table ends near s = 0.35, not 0.2.
recipe-umeyama-2d-quirks = When the SVD gives a reflection (det R < 0), the recipe flips a column of U as Umeyama prescribes but keeps the scale (S1 + S2) / var_x, where Umeyama uses S1 − S2. It matters only for nearly degenerate or very noisy point sets.
