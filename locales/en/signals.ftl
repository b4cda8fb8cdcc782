# The signal pages: #/cubic-path, #/pid-step, #/trapezoid-profile (src/ui/pages/{cubic_path,pid_step,trapezoid_profile}).

## Shared
signals-readouts-title = Readouts
signals-png = Download the plots (PNG)
signals-key-reset = Back to the recipe's defaults
signals-ax-t = time t
signals-unit-s = s
signals-computing = Computing { $rows } rows… { $percent } %. The plot and the readouts show the last run until it is done.

## Cubic path
cubic-plots-title = q, qd and qdd over time
cubic-canvas-label = Plots of the cubic path: position, velocity and acceleration over time. Drag the end point on the position plot.
cubic-drag-hint = Drag the end point (T, q1) on the position plot; hover a plot to read the sample under the cursor. The dots are the samples at dt, the rows of the CSV.
cubic-overlay-quintic = Quintic (zero end accelerations)
cubic-overlay-trapezoid = Trapezoid with the same end time
cubic-series-quintic = Quintic
cubic-series-trapezoid = Trapezoid
cubic-series-cubic = Cubic (recipe)
cubic-ax-q = angle q
cubic-ax-qd = velocity qd
cubic-ax-qdd = acceleration qdd
cubic-unit-rad = rad
cubic-unit-rad-s = rad/s
cubic-unit-rad-s2 = rad/s²
cubic-ro-peak-v = Peak velocity (rad/s)
cubic-ro-peak-v-t = … at t (s)
cubic-ro-peak-a = Peak acceleration (rad/s²)
cubic-ro-peak-a-t = … at t (s)
cubic-ro-a0 = a0 (rad)
cubic-ro-a1 = a1 (rad/s)
cubic-ro-a2 = a2 (rad/s²)
cubic-ro-a3 = a3 (rad/s³)
cubic-ro-rows = Samples (CSV rows)
cubic-ro-cursor-t = Cursor: t (s)
cubic-ro-cursor-q = Cursor: q (rad)
cubic-ro-cursor-qd = Cursor: qd (rad/s)
cubic-ro-cursor-qdd = Cursor: qdd (rad/s²)
cubic-live = q1 { $q1 } rad, T { $T } s: peak velocity { $peak } rad/s.
cubic-key-q1 = Raise or lower the end angle q1 by 0.01 rad (Shift: 0.1)
cubic-key-t = Shorten or lengthen the duration T by 0.01 s (Shift: 0.1)
cubic-explain-what-title = The cubic
cubic-explain-what = q(t) = a0 + a1·t + a2·t² + a3·t³ with q(0) = q0, q(T) = q1 and zero velocity at both ends gives a0 = q0, a1 = 0, a2 = 3·(q1 − q0)/T², a3 = −2·(q1 − q0)/T³. The velocity is a parabola that peaks at 1.5·(q1 − q0)/T at mid-move; the acceleration is a straight line from 6·(q1 − q0)/T² to its negative, so it jumps at both ends. The quintic also starts and ends at zero acceleration, at the price of a higher peak velocity (1.875·(q1 − q0)/T); the trapezoid cruises at a constant speed between two constant accelerations.
cubic-explain-input-title = Input and output
cubic-explain-input = q0, q1 in rad, T in s, dt in s (defaults 0 1.2 1.0 0.02). Output: cubic_path.csv with t_s, q, qd, qdd.
cubic-explain-steps-title = Steps
cubic-explain-steps = 1. Save the script. 2. Run: python cubic_joint_path.py 0 1.2 1.0 0.02 3. Confirm qd ≈ 0 at both ends.
cubic-explain-expected-title = Expected result
cubic-explain-expected = About T/dt + 1 rows; a smooth q from q0 to q1.

## PID step response
pid-plots-title = Output y, setpoint r and controller output u
pid-canvas-label = Plots of the PID step response: the setpoint r and the output y above, the controller output u below, over time.
pid-ghost-note = The grey curves are the previous gains: they stay until the next change, so two tunings can be compared.
pid-ax-y = output y
pid-ax-u = controller u
pid-series-y = output y
pid-series-r = setpoint r
pid-series-u = controller u
pid-series-ghost-y = y, previous gains
pid-series-ghost-u = u, previous gains
pid-ro-rise = Rise time 10–90 % (s)
pid-ro-overshoot = Overshoot (%)
pid-ro-settling = Settling time, 2 % band (s)
pid-ro-sse = Steady-state error r − y (last row)
pid-ro-peak-u = Peak controller output u
pid-ro-peak-u-t = … at t (s)
pid-ro-final-y = Final output y
pid-ro-cursor-t = Cursor: t (s)
pid-ro-cursor-r = Cursor: setpoint r
pid-ro-cursor-y = Cursor: output y
pid-ro-cursor-u = Cursor: controller u
pid-ro-none = not reached
pid-ro-note = Read from the CSV's rows, without interpolation: times are its t column (row k is t = k × 0.05 s, y after that step).
pid-live = Rise time { $rise }, overshoot { $overshoot }, settling time { $settling }.
pid-live-seconds = { $value } s
pid-live-percent = { $value } %
pid-key-kp = Raise or lower Kp by 0.05 (Shift: 0.5)
pid-explain-gains-title = What each gain does
pid-explain-gains = Kp pushes in proportion to the error now: more Kp rises faster but overshoots and, past a point, oscillates. Ki adds up the error over time and removes the offset a P controller leaves, at the price of overshoot and slower settling (wind-up). Kd reacts to how fast the error changes: it damps the overshoot, but on a step it gives a large kick in u at the first sample.
pid-explain-plant-title = The plant
pid-explain-plant = A first-order lag with time constant τ, stepped every dt = 0.05 s: y ← y + a·(u − y) with a = dt / (τ + dt). With τ = 0 the output follows u at once. The setpoint is a unit step, r = 1.
pid-explain-toy-title = Why this is a toy
pid-explain-toy = u is not limited (a real actuator saturates), the derivative acts on the raw error (no filter, so noise and the step itself make spikes), the integral never stops growing while the error stays (no anti-wind-up), and there is no noise, delay or disturbance.
pid-explain-real-title = What a real controller adds
pid-explain-real = Output limits with anti-wind-up, a filtered derivative taken on the measurement rather than the error, setpoint weighting or ramps, a fixed sample time with a real-time guarantee, bumpless switching between manual and automatic, and a safety case: limits, watchdogs and an emergency stop that do not depend on the loop.
pid-explain-input-title = Input and output
pid-explain-input = Kp Ki Kd tau steps (defaults 1.2 0.4 0.05 0.8 80). Output: pid_step.csv with t, r, y, u, e.
pid-explain-steps-title = Steps
pid-explain-steps = 1. Save the script. 2. Run: python pid_step_response.py 3. Inspect the final y against the setpoint 1.0.
pid-explain-expected-title = Expected result
pid-explain-expected = y rises toward 1.0, with the standard library only.

## Trapezoidal profile
trap-plots-title = Position s, velocity v and acceleration a over time
trap-canvas-label = Plots of the trapezoidal profile: position, velocity and acceleration over time, the three phases shaded. Drag vmax and the corner of the ramp on the velocity plot.
trap-drag-hint = On the velocity plot, drag the handle on the dashed line to change vmax, and the corner of the ramp to change amax (its slope).
trap-triangle = Triangle: the distance is too short to reach vmax, so the move brakes as soon as it stops accelerating; the peak velocity is below vmax.
trap-series-profile = the recipe's samples
trap-ax-s = position s
trap-ax-v = velocity v
trap-ax-a = acceleration a
trap-phase-accel = accelerate
trap-phase-cruise = cruise
trap-phase-brake = brake
trap-shape-triangle = triangle (vmax not reached)
trap-shape-trapezoid = trapezoid
trap-ro-shape = Shape
trap-ro-t-acc = Accelerating t_acc (s)
trap-ro-t-flat = Cruising t_flat (s)
trap-ro-t-total = Whole move t_total (s)
trap-ro-v-peak = Peak velocity reached
trap-ro-final-s = Position of the last row
trap-ro-rows = Samples (CSV rows)
trap-ro-cursor-t = Cursor: t (s)
trap-ro-cursor-s = Cursor: position s
trap-ro-cursor-v = Cursor: velocity v
trap-ro-cursor-a = Cursor: acceleration a
trap-live = { $shape }: the move takes { $total } s and peaks at { $peak }.
trap-key-vmax = Raise or lower vmax by 0.01 (Shift: 0.1)
trap-key-amax = Lower or raise amax by 0.01 (Shift: 0.1)
trap-explain-what-title = The profile
trap-explain-what = The move accelerates at amax until it reaches vmax (t_acc = vmax / amax, covering amax·t_acc²/2), cruises at vmax, then brakes at amax to stop at the distance. When the distance is shorter than amax·t_acc², there is no room to cruise: the profile is a triangle that turns at √(distance / amax) and peaks below vmax. Velocity is continuous, acceleration jumps at each phase change (infinite jerk), which is why real drives round the corners (S-curves).
trap-explain-input-title = Input and output
trap-explain-input = distance vmax amax dt (defaults 1.0 0.5 1.0 0.01); the signs are ignored. Output: trap_profile.csv with t, s, v, a.
trap-explain-steps-title = Steps
trap-explain-steps = 1. Save the script. 2. Run: python trapezoid_velocity_profile.py 3. Confirm s ends near the distance.
trap-explain-expected-title = Expected result
trap-explain-expected = The CSV covers accelerate, an optional cruise, and brake.
pid-short = Stops short of r (error { $error }): P action alone leaves a steady-state error, and Ki = { $ki } is too weak to remove it in this run. Add integral action.
pid-tuned = Try tuned gains
