### The page table's strings: each page's title (its heading, the navigation and the tab)
### and one-line description (the loading frame and the home tiles). Loaded with the shell on
### every first visit, whichever page it opens.

home-page-title = Home
home-intro = Short, honest robotics drills that run in your browser: MuJoCo energy, planar IK, trajectory resampling, DH FK, Jacobian and manipulability, cubic paths, SE(3) relative poses and a toy 2D RRT. Practise teleoperation here, on this app's Robot Pilot page; for Isaac Teleop itself, follow Robot Pilot Academy on the BSV site. BSV does not redistribute NVIDIA code.
ik2r-title = Planar 2R IK playground
ik2r-blurb = Solve elbow-down IK, inspect manipulability, export a CSV.
dh-title = DH forward kinematics in 3D
dh-blurb = The recipe's 3R chain in 3D: turn the joints, orbit the view, and walk one modified-DH row through its four elementary transforms.
se3-title = Relative SE(3) pose
se3-blurb = Frames A and B in 3D and T_A⁻¹ T_B drawn from A to B; type or drag the poses, switch between radians and degrees, read the 4×4 matrices.
umeyama-title = Umeyama alignment
umeyama-blurb = Drag the source points, set the true similarity and the noise, and step through how Umeyama’s method recovers scale, rotation and translation.
pendulum-title = Pendulum energy
pendulum-blurb = Swing the recipe's capsule pendulum live, watch its energy drift, run Euler against RK4.
pid-title = PID step response
pid-blurb = Tune Kp, Ki, Kd live on the recipe's toy loop: rise time, overshoot, settling and a ghost of the previous gains.
cubic-title = Cubic path
cubic-blurb = Position, velocity and acceleration of the cubic joint path; drag the end point or the sliders and compare with a quintic or a trapezoid.
trap-title = Trapezoidal profile
trap-blurb = Accelerate, cruise, brake: drag vmax and amax on the velocity plot and watch the phases, and when the move becomes a triangle.
traj-title = Trajectory resampling
traj-blurb = Open a joint trajectory CSV (or use the labeled sample), pick dt, see every joint resampled and download the CSV.
rrt-title = RRT stepper
rrt-blurb = Grow the recipe’s random tree one iteration at a time, backwards too, in a world you draw; see each iteration’s sub-steps.
teleop-nav = Robot Pilot
teleop-blurb = Teleoperate a simulated arm through a whole practice session: record, label, replay, compare, export the evidence.
so101-nav = SO-101
so101-blurb = Fly the SO-101 arm in 3D with Isaac Lab's keyboard and gamepad mapping, through the same practice session: record, label, replay, export the evidence.
drills-title = All drills
drills-blurb = Run any of the twelve drills with your own values and download the same CSV files as the Python recipe.
lesson-title = Lesson
lesson-blurb = Build a lesson from page states and present it with a presenter remote.

## The names of the pages' sections (`data-section`): what a lesson step can bring into view.
section-arm = Arm view
section-drills = Drill tiles
section-recipes = Build recipes
section-tools = Tools compared
section-readouts = Readouts
section-heatmap = Manipulability heatmap
section-sweep = Jacobian sweep plot
section-form = Parameters
section-exports = Downloads
section-explain = Explanation
section-joints = Joints
section-table = DH table
section-row = One row, step by step
section-poses = Poses
section-frames = Frames in 3D
section-matrices = 4×4 matrices
section-rotations = Rotation orders
section-points = Points and fit
section-stepper = Stepper
section-pendulum = Pendulum view
section-plot = Plot
section-world = World view
section-substeps = This iteration's sub-steps
section-device = Input device
section-session = Episodes and evidence
section-wrist = Wrist camera
section-keys = Keys
section-result = Result
section-lessons = Built-in lessons
section-steps = This lesson's steps
section-exercises = Exercises
exercises-load-failed = The exercises could not be loaded: check the connection, then try again.
