# The home page: the BSV page's headline and introduction, the featured in-browser tool and
# one card per recipe (the recipe texts themselves are in recipes.ftl).

home-headline = Robotics: simulate, sample, log — then practice teleop

# The live arm at the top, and what each page's tile shows.
home-tiles-label = Drills that run in your browser
home-arm-label = A two-link arm (L1 0.12 m, L2 0.10 m) inside the ring it can reach
home-arm-hint = Drag the orange tip: both joints follow by inverse kinematics. Drag a link to turn one joint.
home-arm-key-nudge = Move the home arm's tip 5 mm (Shift: 1 mm), with the arm focused
home-arm-open = Open this pose in the IK playground
home-card-more = Inputs, files and command lines
home-featured-label-ik-2r = Kinematics · drag an arm, watch |det J| change
home-featured-label-dh-fk = Kinematics · a DH chain in 3D, row by row
home-featured-label-se3-relative = Kinematics · one frame seen from another
home-featured-label-umeyama-2d = Kinematics · fit rotation, scale and shift to points
home-featured-label-pendulum-energy = Dynamics · energy drift, Euler against RK4
home-featured-label-pid-step = Control · tune Kp, Ki and Kd on a step
home-featured-label-cubic-path = Trajectories · a cubic move, its speed and acceleration
home-featured-label-trapezoid-profile = Trajectories · when a trapezoid becomes a triangle
home-featured-label-traj-resample = Trajectories · resample a joint log to a new rate
home-featured-label-rrt-2d = Planning · a random tree grows toward the goal
home-featured-label-teleop = Teleop practice · drive an arm, record ten demos
home-featured-label-so101 = Teleop in 3D · fly the SO-101 as Isaac Lab does
home-featured-label-drills = Every recipe · your own values, the same CSV files
home-featured-label-lesson = Teaching · chain views into a lesson and present it
home-featured-label-class = Teaching · collect your class's progress files

home-featured-open = Open the playground
home-recipes-heading = Build recipes
home-recipes-intro = Twelve short drills, each a BSV Python recipe rebuilt in Rust. On the command line, “bsv <recipe id>” takes the same values and writes the same CSV files as the Python script.
home-card-inputs = Inputs and defaults
home-card-writes = Writes
home-card-options = Options
home-card-cli = Command line
home-card-python = Python original
home-card-drill = Run this drill
home-card-in-browser = In the browser:
home-card-pairs-ik-2r = Pairs with our IK playground (the one the BSV seed calls the “IK Field Lab”): drag the arm there and watch |det J| change.
home-card-pairs-traj-resample = Runs live on its own page: open your CSV or drop it there, and see every joint resampled.
home-card-pairs-cubic-path = Pairs with the cubic path page: drag the end point and the end time, and watch the velocity and acceleration change.
home-card-pairs-pid-step = Pairs with the PID step page: tune Kp, Ki and Kd live, next to a ghost of the previous gains.
home-card-pairs-trapezoid-profile = Pairs with the trapezoidal profile page: drag vmax and amax and see when the move becomes a triangle.
home-card-pairs-pendulum-energy = Pairs with the pendulum page: watch it swing, and run Euler and RK4 side by side to see the energy drift.
home-card-pairs-rrt-2d = Pairs with the RRT stepper: grow the tree one iteration at a time, backwards too, in a world you draw.
home-card-pairs-umeyama-2d = Pairs with the Umeyama page: drag the points and the true transform, and step through centroids, covariance, SVD, reflection fix, scale and translation.
home-card-pairs-dh-fk = Pairs with the DH page: turn the joints of the chain in 3D, orbit the view, and walk a row through its four elementary transforms.
home-card-pairs-se3-relative = Pairs with the relative pose page: drag frame A or B in 3D, switch radians and degrees, and see the same angles as intrinsic and extrinsic rotations.

# The picture on each recipe card (drawn from the kernel at the defaults), for screen readers.
home-picture-pendulum-energy = Kinetic, potential and total energy of the default pendulum run over time
home-picture-ik-workspace = The reachable points of the default 2R workspace grid, with the unreachable ones in grey
home-picture-traj-resample = The labeled sample trajectory: original points as dots, the resampled joints as lines
home-picture-dh-fk = The default 3R chain drawn in 3D over a ground grid
home-picture-jacobian-2r = The tip positions of the default Jacobian sweep (q1 turning at a fixed q2), seen from above
home-picture-cubic-path = Position and velocity of the default cubic path over time
home-picture-se3-relative = Frames A and B of the default run as coloured axes, with the arrow from A to B
home-picture-rrt-2d = The default RRT tree in the unit square, with the found path in orange
home-picture-pid-step = Setpoint and output of the default PID step response over time
home-picture-manip-grid = Manipulability over the (q1, q2) grid as a colour map, bright is high
home-picture-trapezoid-profile = Velocity of the default trapezoidal profile over time
home-picture-umeyama-2d = Source points, noisy targets and the aligned points of the default Umeyama run, with residuals

# The seed's "Compare the tools" table (outbound links only; nothing is fetched).
home-tools-title = Compare the tools
home-tools-intro = Difficulty is BSV's own rating for a first project. Check each licence on the official page before you ship anything. The links open the official sites; nothing is fetched by this app.
home-tools-caption = Tools the drills point to: what each is for, its licence, difficulty and where it runs
home-tools-col-tool = Tool
home-tools-col-job = Job
home-tools-col-licence = Licence
home-tools-col-difficulty = Difficulty
home-tools-col-where = Local / cloud
home-tools-external = (official site, opens outside the app)
home-tool-mujoco-name = MuJoCo
home-tool-mujoco-job = Rigid-body simulation used in the pendulum recipe
home-tool-mujoco-licence = Apache-2.0
home-tool-mujoco-difficulty = Intermediate
home-tool-mujoco-where = Local
home-tool-mujoco-docs-name = MuJoCo documentation
home-tool-mujoco-docs-job = Model format, sensors, actuators
home-tool-mujoco-docs-licence = Apache-2.0
home-tool-mujoco-docs-difficulty = Intermediate
home-tool-mujoco-docs-where = Local
home-tool-numpy-name = NumPy
home-tool-numpy-job = Arrays for IK grids and trajectory math
home-tool-numpy-licence = BSD-3-Clause
home-tool-numpy-difficulty = Beginner
home-tool-numpy-where = Local
home-tool-isaac-lab-name = Isaac Lab docs
home-tool-isaac-lab-job = Official Isaac Lab install docs
home-tool-isaac-lab-licence = Apache-2.0 (docs)
home-tool-isaac-lab-difficulty = Advanced
home-tool-isaac-lab-where = Cloud / web API
home-tool-isaac-teleop-name = Isaac Capture (Teleop docs)
home-tool-isaac-teleop-job = Official teleoperation docs (NVIDIA; Isaac Capture)
home-tool-isaac-teleop-licence = Apache-2.0 docs site
home-tool-isaac-teleop-difficulty = Advanced
home-tool-isaac-teleop-where = Cloud / web API
home-tool-ros2-name = ROS 2 documentation
home-tool-ros2-job = Robot middleware when you leave pure scripts
home-tool-ros2-licence = Apache-2.0 / open licenses vary by package
home-tool-ros2-difficulty = Intermediate
home-tool-ros2-where = Local + cloud
home-tool-robot-web-tools-name = Robot Web Tools
home-tool-robot-web-tools-job = Browser bridges to ROS (separate from BSV recipes)
home-tool-robot-web-tools-licence = BSD-3-Clause
home-tool-robot-web-tools-difficulty = Intermediate
home-tool-robot-web-tools-where = Cloud / web API

# The line in place of the tiles and cards while their code loads, and if it cannot.
home-more-loading = Loading the drill tiles and the recipe cards…
home-more-failed = The drill tiles and the recipe cards could not be loaded: the network is not reachable. Check the connection, then try again.
