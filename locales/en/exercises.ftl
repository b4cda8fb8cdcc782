# Exercises (src/view/exercises): ex-<id>-prompt, -hint, -explain; a choice exercise also has
# ex-<id>-choice-<n> and ex-<id>-why-<n> (n from 1). A prediction's explanation gets $truth,
# the kernel's value with its unit. Then the words of a page's exercises section
# (src/ui/exercises). Loaded with the section's code, in no page's first load; the progress
# file's and the class page's strings are in progress.ftl.

## #/ik-2r
ex-ik-singular-prompt = Goal: put the arm in a pose whose manipulability w is below 0.001 m², with the tip inside the workspace (not on its edge).
ex-ik-singular-hint = w = l1·l2·|sin q2| depends on the elbow angle only. Which elbow angles make sin q2 small? Stop just short of the edge of the reach.
ex-ik-singular-explain = Near q2 = 0 (stretched) or q2 = π (folded back) both joints move the tip along nearly the same line, so the Jacobian almost loses a direction and w falls toward 0. Those poses lie just inside the workspace's outer and inner circles.
ex-ik-w-pose-prompt = Predict the manipulability w of the pose on screen, in m².
ex-ik-w-pose-hint = For this arm w = |det J| = l1·l2·|sin q2|; read q2 from the pose.
ex-ik-w-pose-explain = w = l1·l2·|sin q2| = { $truth }. It does not depend on q1: turning the whole arm does not change how well it can move its tip.
ex-ik-best-elbow-prompt = At which elbow angle q2 (in degrees, between 0 and 180) does this arm have the largest manipulability?
ex-ik-best-elbow-hint = w = l1·l2·|sin q2|. Where is |sin q2| largest?
ex-ik-best-elbow-explain = w is largest at q2 = { $truth }: with the links at a right angle, the two joints move the tip in perpendicular directions.
ex-ik-singular-where-prompt = Where in its workspace is a two-link planar arm singular?
ex-ik-singular-where-hint = Singular means det J = 0, and det J = l1·l2·sin q2.
ex-ik-singular-where-explain = det J = l1·l2·sin q2 vanishes only at q2 = 0 and q2 = π: the arm straight or folded back, with the tip on the outer or the inner circle of the workspace. Drag the tip to either edge and watch w fall to zero.
ex-ik-singular-where-choice-1 = Only with the tip at the base
ex-ik-singular-where-why-1 = w depends on the elbow angle q2 alone, not on where the tip points; and the tip reaches the base only when l1 = l2.
ex-ik-singular-where-choice-2 = On the outer and the inner circle of the workspace (arm straight or folded back)
ex-ik-singular-where-why-2 = Right: sin q2 = 0 at q2 = 0 and q2 = π, exactly the poses with the tip at l1 + l2 or at |l1 − l2| from the base.
ex-ik-singular-where-choice-3 = Whenever the tip is on the x axis
ex-ik-singular-where-why-3 = q1 only turns the whole arm, and w does not depend on q1.
ex-ik-singular-where-choice-4 = Nowhere: a two-link arm has no singularities
ex-ik-singular-where-why-4 = At q2 = 0 the links are parallel: both joints move the tip the same way, and J loses rank.

## #/dh-fk
ex-dh-tip-height-prompt = Predict the height z of the last frame's origin (frame 3), in metres.
ex-dh-tip-height-hint = Joint 1 sits 0.10 m up; joint 2 pitches the 0.25 m link. Only q2 changes the height.
ex-dh-tip-height-explain = z = 0.10 − 0.25·sin q2 = { $truth }. Joint 1 turns about the vertical and joint 3 turns the last frame in place: neither changes the height.
ex-dh-raise-prompt = Goal: raise the origin of the last frame to 0.3 m or higher.
ex-dh-raise-hint = The height is 0.10 − 0.25·sin q2. Which sign of q2 lifts the link?
ex-dh-raise-explain = A negative q2 pitches the link up; the height reaches 0.3 m once sin q2 ≤ −0.8, and at most 0.35 m with the link straight up.
ex-dh-q3-origin-prompt = Change q3 and keep q1 and q2. What happens to the origin of the last frame?
ex-dh-q3-origin-hint = In modified DH, link i's length a(i−1) comes before joint i.
ex-dh-q3-origin-explain = In modified DH the link length a2 = 0.25 m comes before joint 3, so joint 3 sits at frame 3's origin: q3 turns the frame's axes there and moves nothing.
ex-dh-q3-origin-choice-1 = It stays where it is: q3 turns the frame about its own z axis
ex-dh-q3-origin-why-1 = Right: the 0.25 m length is a2, placed before joint 3, so joint 3 sits at frame 3's origin and only turns it.
ex-dh-q3-origin-choice-2 = It moves on a circle of radius 0.25 m
ex-dh-q3-origin-why-2 = That would need a link after joint 3; in this chain the 0.25 m link comes before it.
ex-dh-q3-origin-choice-3 = It moves up or down
ex-dh-q3-origin-why-3 = Only q2 pitches the link and changes the height.
ex-dh-q3-origin-choice-4 = It swings around the vertical axis
ex-dh-q3-origin-why-4 = That is what q1 does.

## #/se3-relative
ex-se3-distance-prompt = Predict the distance between the origins of frames A and B, in metres.
ex-se3-distance-hint = The relative pose's x, y, z are B's origin in A's frame; a distance does not depend on the frame it is measured in.
ex-se3-distance-explain = √(x² + y² + z²) of the relative position = { $truth }. Turning A changes the three numbers but not this length.
ex-se3-ahead-prompt = Goal: with A turned, place B 0.1 m straight ahead along A's own x axis, facing the same way as A (the relative pose 0.1, 0, 0, 0, 0, 0 within 1 mm and 0.01 rad).
ex-se3-ahead-hint = A's x axis in the world is the first column of A's rotation: for a yaw ψ alone, (cos ψ, sin ψ, 0). B also needs A's roll, pitch and yaw.
ex-se3-ahead-explain = T_A⁻¹ T_B reads B in A's frame: B's origin must be A's origin plus 0.1 m along A's x axis, and B's rotation must equal A's for the relative rotation to vanish.
ex-se3-swap-prompt = Swap A and B. What does the relative pose become?
ex-se3-swap-hint = Write both: T_A⁻¹ T_B and T_B⁻¹ T_A. Multiply them.
ex-se3-swap-explain = T_B⁻¹ T_A is the inverse of T_A⁻¹ T_B: A seen from B. Its position is −Rᵀp: p negated and turned back by the relative rotation, not simply −p.
ex-se3-swap-choice-1 = The same
ex-se3-swap-why-1 = T_B⁻¹ T_A is A seen from B, not B seen from A.
ex-se3-swap-choice-2 = Its inverse
ex-se3-swap-why-2 = Right: (T_A⁻¹ T_B)⁻¹ = T_B⁻¹ T_A.
ex-se3-swap-choice-3 = All six numbers negated
ex-se3-swap-why-3 = The inverse of [R p] is [Rᵀ −Rᵀp]: the position is turned as well, and negating roll, pitch and yaw does not undo a Z·Y·X rotation.
ex-se3-swap-choice-4 = The identity
ex-se3-swap-why-4 = Only when A and B are the same pose.

## #/umeyama-2d
ex-umeyama-angle-prompt = Predict the rotation angle the fit estimates, in degrees.
ex-umeyama-angle-hint = The targets are the points turned by the true angle, scaled and shifted, plus a little noise.
ex-umeyama-angle-explain = The fit estimates { $truth }: close to the true 35°, off only by what the noise moves.
ex-umeyama-exact-prompt = Goal: make the fit exact, its RMSE below 1e-9.
ex-umeyama-exact-hint = What makes the targets differ from a perfect similarity of the points?
ex-umeyama-exact-explain = Without noise (σ = 0) and without a mirror, the targets are exactly a scaled, turned and shifted copy of the points, and the fit recovers it up to rounding.
ex-umeyama-mirror-prompt = Mirror the targets (y → −y before the similarity). What does the fit give?
ex-umeyama-mirror-hint = Umeyama's method looks for s·R with R a rotation, det R = +1.
ex-umeyama-mirror-explain = Mirrored targets would need det R = −1, which no rotation has: the method keeps R a rotation (it flips the last singular direction when det C < 0) and returns the best proper fit, with a large RMSE.
ex-umeyama-mirror-choice-1 = The mirror as well
ex-umeyama-mirror-why-1 = The method removes a reflection on purpose: R stays a rotation.
ex-umeyama-mirror-choice-2 = The best rotation it can find, with a large RMSE
ex-umeyama-mirror-why-2 = Right: a mirror is not a rotation, so the fit returns the closest proper similarity, and the RMSE shows what it cannot explain.
ex-umeyama-mirror-choice-3 = An error: no fit exists
ex-umeyama-mirror-why-3 = A fit always exists; this one is just poor.
ex-umeyama-mirror-choice-4 = A negative scale
ex-umeyama-mirror-why-4 = The scale stays positive: the reflection is handled in R's last singular direction, not by the scale.

## #/pendulum-energy
ex-pendulum-euler-dt-prompt = With Euler at the page's step h, predict the relative energy drift over the whole run: the energy error at the end, in % of E(0).
ex-pendulum-euler-dt-hint = Semi-implicit Euler does not keep the energy exactly; its error shrinks with the step about as h². Try a run with a larger h, then scale.
ex-pendulum-euler-dt-explain = At the end of the run (E + W − E(0)) / E(0) = { $truth }: the capsule's true energy plus the damper's work, against the start. Ten times the step gives about a hundred times the error.
ex-pendulum-period-prompt = Predict the pendulum's period, in seconds, as the page measures it over the run.
ex-pendulum-period-hint = The small-angle formula 2π·√(I / (m g L/2)) holds for small swings only. This one starts at 120°.
ex-pendulum-period-explain = The page measures { $truth } between zero crossings. A large swing is slower than the small-angle period: it spends long near its turning points, where gravity's pull along the arc is weaker than the formula assumes.
ex-pendulum-integrator-prompt = At the page's step h, which integrator ends the run with the smaller energy error?
ex-pendulum-integrator-hint = Turn the comparison on and look at the error plot: its axis is logarithmic.
ex-pendulum-integrator-explain = RK4's energy error stays orders of magnitude below Euler's at the same step: the error plot with the comparison on shows both.
ex-pendulum-integrator-choice-1 = Euler
ex-pendulum-integrator-why-1 = Semi-implicit Euler is first-order: its energy wobbles by an amount that grows with h.
ex-pendulum-integrator-choice-2 = RK4
ex-pendulum-integrator-why-2 = Right: RK4's error per step is far smaller (fourth order), at four evaluations per step.
ex-pendulum-integrator-choice-3 = Both about the same
ex-pendulum-integrator-why-3 = The two errors are many orders of magnitude apart: the error plot shows it.
ex-pendulum-over-top-prompt = Goal: starting below the top, make the simulated pendulum swing over the top, which the real one never does.
ex-pendulum-over-top-hint = Damping takes energy out. Without it, what does a large step do to Euler's energy?
ex-pendulum-over-top-explain = With a large step the integrator itself adds energy until the pendulum goes over the top: an error of the method, not physics.

## #/pid-step
ex-pid-tune-prompt = Goal: tune Kp, Ki and Kd so that, on the page's plant (τ = 0.8 s) over at least the recipe's 80 steps, the overshoot stays below 5 % and the response settles within 2 % before 1.5 s.
ex-pid-tune-hint = The recipe's gains are too slow to settle. More Ki removes the remaining error faster; too much of it overshoots.
ex-pid-tune-explain = A larger Kp speeds up the rise, Ki drives the last error to zero, and a little Kd damps the overshoot. Kp 2, Ki 3, Kd 0.05 overshoots 1.5 % and settles at 1.1 s.
ex-pid-final-y-prompt = Predict the plant output y at the end of the run.
ex-pid-final-y-hint = Does this loop reach the setpoint within the run? Look at how fast the integral term grows.
ex-pid-final-y-explain = y ends at { $truth }. With the recipe's small Ki the integral term is still removing the error when the run stops.
ex-pid-p-only-prompt = Set Ki = 0 and keep Kp = 1.2. Where does y settle in a long run?
ex-pid-p-only-hint = At rest y = u, and u = Kp·e with e = r − y.
ex-pid-p-only-explain = With P alone the loop comes to rest where y = Kp·(1 − y): y = Kp / (1 + Kp) = 0.545 for Kp = 1.2. Only the integral term removes that last error.
ex-pid-p-only-choice-1 = At the setpoint r = 1
ex-pid-p-only-why-1 = P control needs an error to make any output: without the integral term nothing removes the last error.
ex-pid-p-only-choice-2 = Below r, at Kp / (1 + Kp) = 0.545
ex-pid-p-only-why-2 = Right: at rest y = Kp·(1 − y), so y = Kp / (1 + Kp).
ex-pid-p-only-choice-3 = It keeps oscillating
ex-pid-p-only-why-3 = A first-order plant under proportional control comes to rest here: nothing keeps it swinging.
ex-pid-p-only-choice-4 = Above r
ex-pid-p-only-why-4 = y = Kp·(1 − y) puts y below 1 for any positive Kp.
ex-pid-overshoot-prompt = Predict the overshoot of the response with the page's gains, in %.
ex-pid-overshoot-hint = Overshoot is how far the highest y goes above r = 1, as a percentage of r.
ex-pid-overshoot-explain = The highest y passes r by { $truth }. More Ki or less Kd raises it.

## #/cubic-path
ex-cubic-peak-velocity-prompt = Predict the peak joint velocity of the cubic, in rad/s.
ex-cubic-peak-velocity-hint = The cubic starts and ends at rest; its velocity is a parabola, largest halfway.
ex-cubic-peak-velocity-explain = The peak is { $truth }, at t = T/2: 1.5 times the mean speed (q1 − q0) / T.
ex-cubic-speed-limit-prompt = Goal: keep the move from 0 to 1.2 rad, but bring its peak velocity down to 1 rad/s or less.
ex-cubic-speed-limit-hint = The peak is 1.5·(q1 − q0) / T. Which T gives 1 rad/s?
ex-cubic-speed-limit-explain = With T ≥ 1.8 s the peak, 1.5 × 1.2 / T, is at most 1 rad/s: a slower move, the same path.
ex-cubic-peak-accel-prompt = Where is the cubic's acceleration largest in magnitude?
ex-cubic-peak-accel-hint = q̈ = 2a2 + 6a3·t is a straight line in t.
ex-cubic-peak-accel-explain = q̈ = 6Δ/T²·(1 − 2t/T): largest at the start and the end (6Δ/T² = 7.2 rad/s² for the recipe's move), zero halfway.
ex-cubic-peak-accel-choice-1 = In the middle, at T/2
ex-cubic-peak-accel-why-1 = There the velocity peaks and the acceleration is zero.
ex-cubic-peak-accel-choice-2 = At the start and at the end
ex-cubic-peak-accel-why-2 = Right: q̈ = 6Δ/T²·(1 − 2t/T) is largest at t = 0 and t = T (with opposite signs), a jump from zero at each end.
ex-cubic-peak-accel-choice-3 = It is the same all along
ex-cubic-peak-accel-why-3 = That is a trapezoid's ramp; the cubic's acceleration changes linearly.
ex-cubic-peak-accel-choice-4 = At a quarter of the time
ex-cubic-peak-accel-why-4 = q̈ falls linearly from its start value: at T/4 it is only half of it.

## #/trapezoid-profile
ex-trap-triangle-prompt = Goal: change the move so that the profile has no cruise phase (a triangle).
ex-trap-triangle-hint = Speeding up to vmax takes vmax² / (2·amax) of distance, and braking the same again.
ex-trap-triangle-explain = When vmax² / amax ≥ D the move ends before it can reach vmax: it accelerates for half the distance and brakes for the rest.
ex-trap-accel-end-prompt = Predict when the profile stops accelerating, in seconds.
ex-trap-accel-end-hint = Accelerating at amax from rest, how long until vmax? Is the distance long enough to get there?
ex-trap-accel-end-explain = The ramp ends at t = { $truth }: vmax / amax, or √(D / amax) for a triangle.
ex-trap-total-time-prompt = Predict how long the whole move takes, in seconds.
ex-trap-total-time-hint = The two ramps together cover as much distance as cruising at vmax for vmax / amax.
ex-trap-total-time-explain = The move takes { $truth }: D / vmax + vmax / amax for a trapezoid.
ex-trap-short-peak-prompt = With distance 0.2 m, vmax 0.5 m/s and amax 1 m/s², what peak speed does the profile reach?
ex-trap-short-peak-hint = Reaching 0.5 m/s and stopping again would take vmax² / amax of distance.
ex-trap-short-peak-explain = vmax² / amax = 0.25 m is more than the 0.2 m move, so the profile is a triangle: it peaks at √(D·amax) = 0.447 m/s, below vmax.
ex-trap-short-peak-choice-1 = 0.5 m/s, vmax
ex-trap-short-peak-why-1 = Speeding up to 0.5 m/s and braking takes 0.25 m, more than the 0.2 m of the move.
ex-trap-short-peak-choice-2 = 0.447 m/s, √(D·amax)
ex-trap-short-peak-why-2 = Right: a triangle accelerates over half the distance, so v² = 2·amax·D/2 = amax·D.
ex-trap-short-peak-choice-3 = 0.25 m/s
ex-trap-short-peak-why-3 = Half of vmax has no reason here: the peak comes from the distance and amax.
ex-trap-short-peak-choice-4 = 0.2 m/s
ex-trap-short-peak-why-4 = That is the distance, not a speed.

## #/traj-resample
ex-traj-rows-prompt = Predict how many rows (without the header) the resampled table has at the page's dt.
ex-traj-rows-hint = The new grid runs from the first sample's time in steps of dt while it stays at or before the last sample's time.
ex-traj-rows-explain = The table has { $truth } rows: one per grid time from the first sample to the last, the end included when a step lands on it.
ex-traj-miss-peak-prompt = Goal: choose a dt at which the resampled q1 misses the trajectory's highest q1 by at least 0.05 rad.
ex-traj-miss-peak-hint = The peak sits at one sample time. Which grids step over that time?
ex-traj-miss-peak-explain = Linear interpolation only reproduces a sample when a grid time lands on it: a coarse grid that steps over the peak cuts the corner, and the resampled curve never gets as high.
ex-traj-between-prompt = Can the resampled values go above the largest original sample (or below the smallest)?
ex-traj-between-hint = Each new value is computed from the two samples around its time.
ex-traj-between-explain = Linear interpolation puts every new value on the straight line between the two samples around it: it never leaves their range. A cubic spline could.
ex-traj-between-choice-1 = Yes: interpolation overshoots between samples
ex-traj-between-why-1 = That is what a spline can do; a straight line between two samples stays between them.
ex-traj-between-choice-2 = No: every new value lies between the two samples around it
ex-traj-between-why-2 = Right: np.interp draws straight lines between neighbouring samples.
ex-traj-between-choice-3 = Only when dt is smaller than the spacing of the samples
ex-traj-between-why-3 = The step does not matter: any grid time falls on one of the straight segments.

## #/rrt-2d
ex-rrt-300-prompt = Goal: move or resize the boxes so that with seed 7 the tree reaches the goal, but only after more than 300 iterations.
ex-rrt-300-hint = The recipe's world takes 120 iterations. Make the way around longer without closing it.
ex-rrt-300-explain = A narrow or long detour leaves fewer random samples that extend the tree toward the goal, so more iterations are spent; the goal must stay reachable.
ex-rrt-path-length-prompt = Predict the length of the path the run finds, in units of the square's side.
ex-rrt-path-length-hint = The straight line from start to goal crosses the box, and the tree's path is made of steps of 0.05 that zigzag.
ex-rrt-path-length-explain = The path is { $truth } long: it goes around the box, and an RRT's path is far from the shortest.
ex-rrt-corner-prompt = An edge of the tree cuts across a corner of a box, yet the planner accepted it. Why?
ex-rrt-corner-hint = Look at how an edge is checked: the sub-step shows its check points.
ex-rrt-corner-explain = Each edge is checked at 12 evenly spaced points only; a corner thinner than their spacing can fall between two of them and be cut.
ex-rrt-corner-choice-1 = Only 12 points of each edge are checked, and a thin corner between two of them is missed
ex-rrt-corner-why-1 = Right: the recipe checks 12 evenly spaced points; a corner that fits between two of them is cut.
ex-rrt-corner-choice-2 = Box edges and corners do not count as inside
ex-rrt-corner-why-2 = The boxes are closed: a point on an edge collides.
ex-rrt-corner-choice-3 = The goal bias lets edges toward the goal pass through boxes
ex-rrt-corner-why-3 = The goal bias only chooses where to sample; every edge is checked the same way.
ex-rrt-corner-choice-4 = The step is longer than the box
ex-rrt-corner-why-4 = The step, 0.05, is much shorter than the box; what matters is the spacing of the check points.
ex-rrt-wall-prompt = Goal: place the boxes so that the tree cannot reach the goal within the run (at least 800 iterations, the goal itself outside every box).
ex-rrt-wall-hint = The boxes can touch the square's edges. What does the tree need to get past?
ex-rrt-wall-explain = A closed wall leaves no free path: a complete planner would say so, but an RRT just spends its whole budget. Running out of iterations never proves that no path exists.

## #/teleop
ex-teleop-near-singular-prompt = Goal: drive the arm into a pose whose manipulability w is below 0.001 m², within the joints' limits.
ex-teleop-near-singular-hint = Only the elbow angle q2 changes w = l1·l2·|sin q2|. Stretch the arm out (or fold it) slowly.
ex-teleop-near-singular-explain = Near q2 = 0 the arm is almost straight: w falls toward zero, and a hand command along the arm needs ever larger joint speeds.
ex-teleop-which-joint-prompt = Which joint's angle decides whether the 3R arm is singular?
ex-teleop-which-joint-hint = Subtract neighbouring columns of J: det J = l1·l2·sin q2.
ex-teleop-which-joint-explain = det J = l1·l2·sin q2: the elbow alone decides it. The shoulder turns the whole arm, and the wrist's column can be subtracted from the others, which removes it from the determinant.
ex-teleop-which-joint-choice-1 = The shoulder, q1
ex-teleop-which-joint-why-1 = q1 turns the whole arm: w is the same at every q1.
ex-teleop-which-joint-choice-2 = The elbow, q2
ex-teleop-which-joint-why-2 = Right: det J = l1·l2·sin q2 vanishes at q2 = 0 and q2 = ±π.
ex-teleop-which-joint-choice-3 = The wrist, q3
ex-teleop-which-joint-why-3 = Subtracting the wrist's column from the others removes l3 from the determinant: q3 never changes it.
ex-teleop-calm-method-prompt = With the arm nearly straight, the same small hand command goes to pinv and to DLS. Which gives the smaller joint step?
ex-teleop-calm-method-hint = pinv inverts J exactly; DLS adds λ² to J Jᵀ before inverting.
ex-teleop-calm-method-explain = Near a singularity J⁻¹ grows like 1/σ_min, so pinv asks for huge joint steps; DLS's λ² keeps J Jᵀ + λ² I away from singular, trading a little tracking error for calm joints.
ex-teleop-calm-method-choice-1 = pinv
ex-teleop-calm-method-why-1 = Its step grows like 1/σ_min: without damping nothing limits it near the singularity.
ex-teleop-calm-method-choice-2 = DLS
ex-teleop-calm-method-why-2 = Right: the damping λ² bounds the step, at the cost of a small error in the hand's motion.
ex-teleop-calm-method-choice-3 = Both the same
ex-teleop-calm-method-why-3 = They agree far from singularities, where λ² is tiny beside J Jᵀ; near one they differ by orders of magnitude.

## #/so101
ex-so101-low-w-prompt = Goal: bring the SO-101 to a pose whose manipulability w is below 0.001 m³, with every joint within its range.
ex-so101-low-w-hint = w falls where the arm is stretched out or folded up. Try bending the elbow far.
ex-so101-low-w-explain = With the elbow folded the tool's possible motions flatten: one direction of the velocity ellipsoid shrinks, and so does its volume w.
ex-so101-pan-prompt = Turn the shoulder pan (joint 1) and keep the other joints. What happens to w?
ex-so101-pan-hint = The pan joint turns the whole arm about the vertical axis.
ex-so101-pan-explain = Turning the whole arm about the vertical turns its velocity ellipsoid with it, without changing its shape: w stays the same.
ex-so101-pan-choice-1 = It stays the same
ex-so101-pan-why-1 = Right: the pan turns the arm rigidly, and a turned ellipsoid has the same volume.
ex-so101-pan-choice-2 = It grows as the arm turns toward the side
ex-so101-pan-why-2 = Nothing about the arm's shape changes with the pan; only its heading does.
ex-so101-pan-choice-3 = It falls to zero at ±90°
ex-so101-pan-why-3 = Singular poses come from the shape of the arm (stretched, folded), not from where it points.
ex-so101-five-joints-prompt = The SO-101 has five joints; the tool's pose has six numbers (x, y, z and three angles). What follows?
ex-so101-five-joints-hint = Count the columns of the 6×5 Jacobian: how many independent tool motions can five joint speeds make?
ex-so101-five-joints-explain = Five joint speeds make at most five independent tool motions out of six: J Jᵀ (6×6) is singular at every pose, so at each position some orientations are out of reach, and the IK can only come as close to a commanded motion as those five allow.
ex-so101-five-joints-choice-1 = It can take any position with any orientation within its reach
ex-so101-five-joints-why-1 = That needs six independent motions; five joints give at most five.
ex-so101-five-joints-choice-2 = Not every orientation at every position: one direction of the tool's motion is always missing
ex-so101-five-joints-why-2 = Right: the 6×5 Jacobian has rank five at most.
ex-so101-five-joints-choice-3 = It has a joint to spare (it is redundant)
ex-so101-five-joints-why-3 = A redundant arm has more joints than the task has numbers; this one has fewer.

## A page's exercises section (src/ui/exercises)
exercises-lede = Predict first, then check: the page's own kernel judges every answer. { $done } of { $total } done.
exercise-kind-predict = Predict
exercise-kind-goal = Goal
exercise-kind-choose = Choose
exercise-state-open = To do
exercise-state-predicting = Predicting
exercise-state-wrong = One more try
exercise-state-right = Right
exercise-state-revealed = Answer shown
exercise-state-done = Done
exercise-prediction-label = Your prediction
exercise-commit = Check
exercise-hint = Hint
exercise-reveal = Show the answer
exercise-again = Try again
exercise-prediction-empty = Type a number first.
exercise-prediction-comma = Write decimals with a point (0.5), without commas.
exercise-prediction-not-a-number = This is not a number: type one such as 0.25, −3 or 1e-3.
exercise-verdict-wrong = Your { $value } is too { $direction ->
    [high] high
   *[low] low
}: not within { $tolerance } of the page's value. Read the hint, then try once more.
exercise-verdict-right = Right: your { $value } against the page's { $truth } (within { $tolerance }).
exercise-verdict-revealed = The page's value is { $truth }; your { $value } is not within { $tolerance } of it.
exercise-verdict-shown = The page's value is { $truth }.
exercise-no-truth = The page as it stands has no value to check this against (a run too short, a goal not reached): change it, then try again.
exercise-check-failed = This cannot be checked on the page as it stands: { $detail }
exercise-choice-right = Right. { $why }
exercise-choice-wrong = Not this one. { $why }
exercise-choice-revealed = The answer is “{ $choice }”. { $why }
exercise-goal-open = Not met yet: use the page above until it is.
exercise-goal-met-by-link = The page already meets this goal as its link opened it: change something on the page, keeping the goal met, to count it.
exercise-goal-done = Met: done.
exercise-done-first-try = Done, right at the first try.
exercise-done-later = Done.
