# Robot Pilot on the SO-101 (#/so101).
so101-title = Robot Pilot: SO-101
so101-head-lede = Live as the page opens: fly the tool to the blue cube, grip it and carry it into the green square.
so101-lede = The Academy's own arm: TheRobotStudio's SO-101, five joints and a gripper, its kinematics taken from the public SO-ARM100 description and checked against MuJoCo. Each 10 ms step turns your six-axis command into joint motion as Isaac Lab's differential IK controller does in relative pose mode. Fly the tool with W/S, A/D and Q/E, close and open the gripper with K; Space pauses and resumes.
so101-canvas-label = The SO-101 over the table, with the cube, the goal square and, when set, the wall. W/S move the tool along x, A/D along y, Q/E along z; Z/X, T/G, C/V turn it about x, y, z; K opens or closes the gripper, R resets, Space engages or pauses. Drag an arrow or a ring on the tool to move or turn it while you hold it; drag elsewhere to orbit.
so101-wrist-label = The wrist camera: the scene seen from the gripper, looking along it.
so101-wrist-caption = Wrist camera: the view from the gripper, as pilots use it to line up a grasp.
so101-key-x = move the tool along x (forward / back)
so101-key-y = move the tool along y (left / right)
so101-key-z = move the tool along z (up / down)
so101-key-roll = turn the tool about x (roll)
so101-key-pitch = turn the tool about y (pitch)
so101-key-yaw = turn the tool about z (yaw)
so101-ro-x = Tool x
so101-ro-y = Tool y
so101-ro-z = Tool z
so101-ro-roll = Roll
so101-ro-pitch = Pitch
so101-ro-yaw = Yaw
so101-ro-q1 = Shoulder pan
so101-ro-q2 = Shoulder lift
so101-ro-q3 = Elbow flex
so101-ro-q4 = Wrist flex
so101-ro-q5 = Wrist roll
so101-ro-manipulability = Manipulability
so101-ro-orientation-error = Orientation error
so101-ro-tool-caption = Control and tool
so101-ro-joints-caption = Joints
so101-col-readout = Readout
so101-col-value = Value
so101-col-unit = Unit
so101-col-limit = Limits
so101-orientation-why = Orientation error is the turn you asked for that the arm did not make: with five joints the SO-101 can point its gripper but has no joint to tilt it sideways, so a roll or yaw it cannot reach is left out and shows here.
so101-label-title = Label episode { $n }
so101-label-proposal = Proposed: { $label } { $category }
so101-session-line = { $count ->
    [0] Pilot id “{ $pilot }”: no episodes yet.
    [one] Pilot id “{ $pilot }”: 1 episode, { $unlabelled } not labelled.
   *[other] Pilot id “{ $pilot }”: { $count } episodes, { $unlabelled } not labelled.
}
so101-summary-title = Repeatability summary
so101-field-obstacle = Wall between the cube and the goal
so101-settings-note = Changing a setting starts a new episode; the one in progress is kept, marked interrupted.
so101-pad-map = Gamepad (Isaac Lab's Se3Gamepad): left stick x and y, right stick up/down z and left/right yaw, D-pad up/down pitch and left/right roll, X toggles the gripper; dead zone 0.01.
so101-pointer-map = Touch or mouse: drag a coloured arrow on the tool to move along it, or the ring of the same colour to turn about that axis (red x: roll, green y: pitch, blue z: yaw); it moves only while you hold it. The buttons engage, open or close the gripper and reset.
so101-source = Kinematics: TheRobotStudio SO-ARM100 (Apache-2.0), Simulation/SO101/so101_new_calib.xml at commit fda892c; links drawn as the boxes around their collision meshes.
so101-state-replay = replaying
so101-state-ended = ended
so101-ended-success = Success! Kept as episode { $n }.
so101-ended-timeout = Time is up. Kept as episode { $n }.
so101-ended-pilot = Episode ended. Kept as episode { $n }.
so101-ended-practice = Episode over (practice: not recorded). Go to Record ten to keep your attempts.
so101-live-pose = Tool at x { $x } mm, y { $y } mm, z { $z } mm; gripper { $gripper }; orientation error { $error }°.
so101-review-empty = No episode to replay yet: record one in Record ten (or open a saved session), then review it here step by step.
so101-open-note = To continue or review a saved session, choose its files together: teleop_session_evidence.json, so101_episodes.csv and every so101_episode_<n>.csv.
so101-grasp-rule = Grasp rule: closing the gripper holds the cube only when the tool frame is within 2 cm of the cube's centre and the jaws close square to it (within 25° of a face); any other close is a missed grasp. Turn the tool with C/V (yaw) to line the jaws up with the cube's sides; the wrist camera turns with the wrist.
so101-files-unloaded = The part of this page that writes and reads session files could not be loaded (offline, or the server did not answer). Your session is kept; check the connection, then download or open again.
so101-dataset-button = LeRobot dataset (v3.0, zip)
so101-dataset-note = The LeRobot dataset holds the labelled episodes at 25 frames per second (every 4th step of the 100 Hz simulation): joint positions and the commanded joint targets as LeRobot's SO-101 follower writes them, the cube and the goal, success from your label. Unzipped, LeRobotDataset(repo_id, root=<folder>) loads it as it is; "bsv so101-dataset" writes the same files from the episode CSVs.
so101-dataset-writing = Writing the LeRobot dataset: { $done } of { $total } labelled episodes…
so101-dataset-done = { $file } written: { $total ->
    [one] 1 labelled episode
   *[other] { $total } labelled episodes
}, { $kb } KB. The evidence now lists it with its SHA-256.
so101-dataset-none = Label an episode first: only labelled episodes go into the dataset.
so101-dataset-failed = The LeRobot dataset could not be written: { $detail }
so101-dataset-unloaded = The dataset writer could not be fetched (is the connection down?). Click again to retry.
so101-dataset-failed-replay = The LeRobot dataset could not be written: labelled episode { $n } (in the order of the table) does not replay at step { $step }; it was changed after it was recorded.
