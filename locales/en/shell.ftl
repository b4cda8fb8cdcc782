# The app shell: header, navigation, language switch, projector mode, footer, the `?`
# shortcut overlay, the not-found page and the crash banner.

app-name = BSV Playground
# The brand on phone-width screens (the full name is still read out).
app-name-short = BSV
app-subtitle = Robotics drills that run in your browser

skip-to-content = Skip to content

nav-label = Pages
nav-home = Home
nav-drills-menu = Drills
nav-group-kinematics = Kinematics
nav-group-dynamics = Dynamics and control
nav-group-trajectories = Trajectories
nav-group-planning = Planning

lang-switch-title = Show this page in Japanese (key: L)
projector-toggle = Projector
projector-toggle-title = Projector mode: larger type, thicker lines, high contrast (key: P)
help-button-label = Keyboard shortcuts (key: ?)
help-failed = Could not load the list of keyboard shortcuts. Check the connection and press “?” again.
share-button = Share
share-button-title = This page's link as a QR code to scan (key: S while presenting)
share-failed = Could not load the QR code. Check the connection and try again.
share-title = Scan to open this page
share-qr-label = QR code of this page's link
share-link-label = Or type the link:
share-too-long = This link is too long for a QR code; share the link below.

footer-disclaimer = Research, education and simulation only. Nothing here is a safety-rated controller, a real-hardware authority, or a claim that BSV ran your robot. Real hardware stays with the owner or partner.
footer-offline = Works offline; no data leaves this page.

overlay-title = Keyboard shortcuts
overlay-close = Close
overlay-shell-heading = Everywhere
overlay-page-heading = On this page
overlay-page-none = This page has no keys of its own.
overlay-access = Tab reaches every control; a drawing you can drag also takes keys once focused (listed above). Plot colours are the colour-blind-safe Okabe–Ito set and heatmaps use viridis; with your system's “reduce motion” setting nothing plays by itself.
overlay-note = Everywhere keys do nothing while you type in a field. Page keys work while the page or its drawing has focus, not while a button, link or field has it (click the page first); on the Robot Pilot pages the keys that fly the arm (and K and R) work whatever has the focus, except a field you type in or an open dialog. While a lesson is presented, a remote's keys work whatever has the focus: PageDown or → goes on, PageUp or ← goes back, B or . blacks the screen and brings it back, Esc ends (in a field you type in, ← and → move the caret).
key-help = Show or hide this list
key-projector = Projector mode on or off
key-lang = Switch between English and Japanese
key-escape = Close this list
key-sections = Next / previous section of the page (what a presenter remote's buttons send); past the last section, the next drill. On a page that steps, they step.

notfound-title = Page not found
notfound-body = There is no page at this address. It may be an old or mistyped link.
notfound-home = Go to the home page

page-mount-failed = This page could not be opened. Details are in the browser console.
page-loading = Loading this drill…
page-load-failed = This drill could not be loaded: the network is not reachable, or a file of the app is missing. Check the connection, then try again.
page-load-retry = Retry

crash-title = Something went wrong.
crash-body = Your work is kept in the address (URL), so reloading picks up where you left off.
crash-reload = Reload the page

# The "next step" chain at the foot of every drill page (the seed's sentences).
chain-label = Drill chain
chain-title = Next step
chain-step-pendulum-energy = Pendulum energy
chain-step-ik-workspace = IK workspace
chain-step-traj-resample = Trajectory resampling
chain-step-dh-fk = DH forward kinematics
chain-step-jacobian-2r = Jacobian sweep
chain-step-cubic-path = Cubic path
chain-step-se3-relative = Relative SE(3) pose
chain-step-rrt-2d = 2D RRT
chain-step-pid-step = PID step response
chain-step-manip-grid = Manipulability grid
chain-step-trapezoid-profile = Trapezoidal profile
chain-step-umeyama-2d = Umeyama alignment
chain-step-teleop = Robot Pilot practice
chain-step-so101 = Robot Pilot: SO-101
chain-next-pendulum-energy = Sample a planar IK workspace next, or open Robot Pilot for teleop practice.
chain-next-ik-workspace = Resample a joint trajectory, or practice teleop resets in Robot Pilot.
chain-next-traj-resample = Run DH forward kinematics on a small angle set.
chain-next-dh-fk = Compute a planar 2R Jacobian and manipulability sweep next.
chain-next-jacobian-2r = Build a cubic joint path between two waypoints next.
chain-next-cubic-path = Compute a relative SE(3) pose between two frames.
chain-next-se3-relative = Run a toy 2D RRT around a box obstacle.
chain-next-rrt-2d = Run a discrete PID step response next.
chain-next-pid-step = Map 2R manipulability next.
chain-next-manip-grid = Build a trapezoidal velocity profile next.
chain-next-trapezoid-profile = Align 2D point clouds with Umeyama next.
chain-next-umeyama-2d = Open Robot Pilot Academy, or revisit planar IK.
chain-next-teleop = Fly the Academy's own arm, the SO-101, in 3D next.

# The offline install's update offer.
update-ready = A new version of BSV Playground is ready. The page keeps running this one until you reload.
update-reload = Reload to update

## The lesson bar: "+ Lesson" on every page, and the presenter's bar
lesson-add = + Lesson
lesson-add-title = Add this view to the lesson (edit it on the Lesson page)
lesson-added = Added as step { $count } of the lesson.
lesson-added-unsaved = Added as step { $count } of the lesson, but this browser's storage is full: the lesson is not saved and lives in this tab only.
lesson-add-failed = Could not load what adds a view to the lesson. Check the connection and press “+ Lesson” again.
lesson-bar-label = Lesson
lesson-end = End lesson
lesson-next = Next →
lesson-page-steps-left = { $count } page steps before the next lesson step
lesson-goals-label = The goal of this step
lesson-goal-below = { $readout } < { $value } { $unit }
lesson-goal-above = { $readout } > { $value } { $unit }
lesson-goal-within = { $readout } within { $value } ± { $tolerance } { $unit }
lesson-goal-met = ✓ met
lesson-goal-open = not yet
lesson-prev = ← Back
lesson-step = Step
lesson-untitled = My lesson

# An embedded page (`embed=1`): the link to the same page and state in a tab of its own.
embed-open = Open in BSV Playground ↗
embed-open-title = Opens this drill, as it is now, in a new tab
