# Lessons: the #/lesson page, the header's "add this view" button and the presenter bar.

lesson-intro = A lesson is a list of page states, each with a title and a note for you. On any page, set things up and press “+ Lesson” in the header to add what you see. Present it full screen: Page Down / → goes on (first stepping the page when a step asks for it), Page Up / ← goes back, Esc ends. The lesson is kept in this browser, and its link or .json file carries it to another.
lesson-builtin-heading = Built-in lessons (about 10 minutes each)
lesson-builtin-ik-title = IK, the Jacobian and singularities
lesson-builtin-ik-1-title = The IK playground
lesson-builtin-ik-1-note = The arm on its elbow-down branch (set by this step’s link). Drag the tip around: ask which joint angles put it there, and where the elbow would be on the other branch.
lesson-builtin-ik-2-title = Near the stretched-out arm
lesson-builtin-ik-2-note = q2 = 0.05: the arm is nearly straight. On the heatmap the white circle sits next to the red dashed line q2 = 0, where |det J| falls to zero all along the line.
lesson-builtin-ik-3-title = The Jacobian sweep
lesson-builtin-ik-3-note = The same pose, the jacobian-2r sweep over q1: σ_min against σ_max. The lines are flat because they depend on q2 only; at q2 = 0.05 σ_min is almost zero. Ask what a small σ_min means for a controller.
lesson-builtin-ik-4-title = Teleop near the singularity
lesson-builtin-ik-4-note = This step’s link sets the IK method to pinv: no damping. Drive the arm toward full stretch and watch the joints lurch as it nears the singularity; DLS damps exactly that.
lesson-builtin-energy-title = Integrators and energy
lesson-builtin-energy-1-title = An undamped pendulum
lesson-builtin-energy-1-note = No damping (set by this step’s link): the pendulum swings back to the same height every time. Ask where its speed peaks.
lesson-builtin-energy-2-title = Euler against RK4
lesson-builtin-energy-2-note = The comparison is on: Euler and RK4 from the same start. The error panel plots the energy error on a log axis: which integrator’s error keeps growing?
lesson-builtin-energy-3-title = A bigger timestep
lesson-builtin-energy-3-note = h = 0.01 s, five times the default (set by this step’s link). The class predicts Euler’s relative energy drift over the run, each on paper or a phone; “next” shows the true value beside the prediction, with why.
lesson-builtin-energy-4-title = A feedback loop
lesson-builtin-energy-4-note = PID on a first-order plant: the output y climbs to the setpoint r, and the lower panel shows the controller output u. Read the overshoot and the settling off the plot.
lesson-builtin-planning-title = Planning and trajectories
lesson-builtin-planning-1-title = Stepping the RRT
lesson-builtin-planning-1-note = Five presses grow the tree five iterations: each draws a sample, finds the nearest node and steers one step toward it. Every tenth sample is the goal: ask why.
lesson-builtin-planning-2-title = A cubic path
lesson-builtin-planning-2-note = Zero velocity at both ends: the velocity qd peaks halfway, where the acceleration qdd crosses zero. Ask why a cubic cannot also start with zero acceleration.
lesson-builtin-planning-3-title = The trapezoid
lesson-builtin-planning-3-note = The goal: a profile with no cruise at all, a triangle. Ask what a shorter move or a gentler acceleration does to the flat top, then let the class try; the goal turns green the moment it is met.
lesson-builtin-planning-4-title = Resampling a trajectory
lesson-builtin-planning-4-note = Real logs are not evenly timed. The dots are the file’s samples, the line the series resampled at a fixed dt: compare them.
lesson-edit-heading = This lesson
lesson-name-label = Lesson title
lesson-empty = No steps yet. Open any page, set it up and press “+ Lesson” in the header, or load a built-in lesson above.
lesson-builtin-shown = This is a built-in lesson, ready to present: you have no lesson of your own yet. Editing it or loading another makes it yours; “+ Lesson” on any page starts a new one of your own.
lesson-present = Present
lesson-export = Export .json
lesson-import = Import .json…
lesson-clear = Remove all steps
lesson-link-label = Link to this lesson
lesson-replace-confirm = Replace the current lesson with the built-in one? Export it first if you want to keep it.
lesson-clear-confirm = Remove every step of this lesson?
lesson-step-up = ↑
lesson-step-up-label = Move step { $n } up
lesson-step-down = ↓
lesson-step-down-label = Move step { $n } down
lesson-step-present = Present from here
lesson-step-present-label = Present from here (step { $n })
lesson-step-delete = Delete
lesson-step-delete-label = Delete step { $n }
lesson-step-title-label = Title
lesson-step-note-label = Note for the presenter
lesson-step-page-steps-label = Page steps before moving on
lesson-step-focus-label = Show on screen
lesson-step-focus-main = The page's main view
lesson-step-exercise-label = Exercise (its answer hidden until “next”)
lesson-step-exercise-none = None
lesson-step-goals-label = Your goal (checked live while presenting; up to 3 conditions)
lesson-goal-readout-label = Readout
lesson-goal-op-label = Condition
lesson-goal-op-below = less than
lesson-goal-op-above = more than
lesson-goal-op-within = within ± of
lesson-goal-value-label = Value
lesson-goal-tolerance-label = Tolerance
lesson-goal-remove = Remove
lesson-goal-add = Add a goal
lesson-goal-invalid = Type a number (and for “within” a tolerance of 0 or more); the last good condition is kept.
lesson-focus-unknown = Step { $step }: the page “{ $page }” has no section “{ $focus }”, so this step shows the page's main view.
lesson-page-steps-invalid = A whole number from 0 to { $max }.
lesson-error-not-text = This file could not be read as a lesson: { $detail } The current lesson is kept.
lesson-error-too-big = This file is { $size } ({ $bytes } bytes); a lesson file may be at most { $limit }. It was not read. The current lesson is kept.
lesson-error-empty-file = This file is empty. The current lesson is kept.
lesson-error-too-deep = This file nests lists or objects more than { $max } deep (line { $line }, column { $column }); a lesson nests 3 deep. The current lesson is kept.
lesson-error-not-json = This file is not JSON: the text stops making sense at line { $line }, column { $column }. The current lesson is kept.
lesson-error-not-an-object = This JSON file holds { $kind ->
    [array] a list
    [text] a piece of text
    [number] a number
    [boolean] true or false
    *[other] null
}, not a lesson. The current lesson is kept.
lesson-error-step-not-an-object = Step { $step } is not an object with a route and a title. The current lesson is kept.
lesson-error-no-format = This JSON file is not a BSV lesson: it has no “format” field (a lesson file says "format": "bsv-lesson"). The current lesson is kept.
lesson-error-format = This file is not a BSV lesson (format “{ $found }”, expected “bsv-lesson”). The current lesson is kept.
lesson-error-version = This lesson was written by another version (version { $found }; this app reads version { $version }). The current lesson is kept.
lesson-error-unknown-field = The lesson has a field this app does not know: “{ $field }”. The current lesson is kept.
lesson-error-step-unknown-field = Step { $step } has a field this app does not know: “{ $field }”. The current lesson is kept.
lesson-error-missing-field = The lesson has no “{ $field }” field. The current lesson is kept.
lesson-error-step-missing-field = Step { $step } has no “{ $field }” field. The current lesson is kept.
lesson-error-wrong-type = The lesson's field “{ $field }” must be { $expected ->
    [text] text
    [number] a whole number
    *[list] a list of steps
}. The current lesson is kept.
lesson-error-step-wrong-type = Step { $step }, field “{ $field }”: must be { $expected ->
    [text] text
    [number] a whole number
    *[list] a list
}. The current lesson is kept.
lesson-error-no-steps = This lesson has no steps: there is nothing to present. The current lesson is kept.
lesson-error-too-many-steps = A lesson holds at most { $max } steps; this one has { $count }. The current lesson is kept.
lesson-error-unknown-page = Step { $step }, field “route”: this app has no page “{ $page }”. The current lesson is kept.
lesson-error-too-long = Step { $step }, field “{ $field }”: longer than { $max } characters. The current lesson is kept.
lesson-error-page-steps = Step { $step }, field “pageSteps”: must be a whole number from 0 to { $max }. The current lesson is kept.
lesson-error-unknown-exercise = Step { $step }, field “exercise”: the page “{ $page }” has no exercise “{ $exercise }”. The current lesson is kept.
lesson-error-goal = Step { $step }, goal { $goal }: a goal is up to { $max } conditions, each a readout of the page, “<”, “>” or “within”, a number, and for “within” a tolerance of 0 or more. The current lesson is kept.
lesson-error-title-too-long = The lesson's field “title” is longer than { $max } characters. The current lesson is kept.
lesson-unsaved = This lesson is not saved: this browser's storage is full (or turned off). It stays on this page while the tab is open; export it as .json to keep it.
lesson-unreadable = The lesson stored in this browser could not be read (edited by hand or cut short), so this page started clean. Its text is kept in this browser's storage under { $key }.
lesson-unreadable-download = Download the kept text
lesson-unreadable-forget = Discard it
lesson-present-two = Present on two screens
present-two-blocked = The browser blocked the second window. Allow pop-ups for this site, then press “Present on two screens” again.
lesson-present-failed = The code for presenting could not be fetched. Check the connection and try again.
present-two-label = Presenter view
present-two-now = Now
present-two-next = Next
present-two-last = End of the lesson
present-two-elapsed = Time since the start
present-two-picture = Next step: { $title }
present-two-black = Black screen
present-two-unblack = Show the screen
present-two-blacked = The room’s screen is black (B or . brings it back).
