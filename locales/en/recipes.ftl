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
recipe-manip-grid-blurb = Sample |det J| over a joint grid. Pairs with the Planar 2R IK playground.
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
