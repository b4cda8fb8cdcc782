# The home page: the BSV page's headline and introduction, the featured in-browser tool and
# one card per recipe (the recipe texts themselves are in recipes.ftl).

home-page-title = Home
home-headline = Robotics: simulate, sample, log — then practice teleop
home-intro = Build short, honest simulation drills: MuJoCo energy, planar IK, trajectory resample, DH FK, Jacobian/manipulability, cubic paths, SE(3) relatives and a toy 2D RRT. For Isaac Teleop practice, use Robot Pilot Academy — BSV does not redistribute NVIDIA code.
home-featured-label = Interactive tool, runs in your browser (English / Japanese)
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
