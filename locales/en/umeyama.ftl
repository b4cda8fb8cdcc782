## The Umeyama alignment page (#/umeyama-2d)
umeyama-lede = The umeyama-2d recipe’s points X, the noisy targets Y = s R X + t + noise, and the similarity Umeyama’s closed form recovers from them. Drag a point, click empty space to add one, or drag the violet handles to change the true translation and rotation; then step through the fit.
umeyama-edited = Edited: these points or this true similarity are not the Python recipe’s, so this run no longer matches it. The command line below carries the options that reproduce it with bsv, and umeyama_points.csv holds X, Y and the aligned points.
umeyama-more-loading = Loading the downloads and the command lines… The points, the fit and the steps already work.
umeyama-more-failed = The downloads and the command lines could not be loaded: the network is not reachable. The points, the fit, the steps and the parameters still work. Check the connection, then try again.
umeyama-view-title = Points and fit
umeyama-canvas-label = The plane with the source points X (blue discs, numbered by order), the noisy targets Y (orange squares), the aligned points s R X + t (green rings), the residuals (red dashes) and the true translation and rotation handles (violet). Keys: right arrow next step, left arrow previous step, n selects the next point (Shift + n the previous), Shift + arrows move the selected point, Delete removes it, a adds a point.
umeyama-legend-x = X: source points (drag)
umeyama-legend-y = Y: noisy targets
umeyama-legend-aligned = aligned: s R X + t
umeyama-legend-residual = residual
umeyama-legend-truth = true t and s·R (drag)
umeyama-action-add = Add a point
umeyama-action-remove = Remove the selected point
umeyama-action-mirror = Mirror preset
umeyama-action-recipe = The recipe’s points and truth
umeyama-view-note = Click or tap empty space to add a point there (at most 40); select a point by clicking it. Each point keeps the recipe’s noise for its place in the list, so moving one point moves only its own target.
umeyama-refused-too-many = There are already { $count } points, the most this page holds.
umeyama-refused-too-few = A similarity needs at least { $count } points; this one stays.
umeyama-png = Download the view (PNG)
umeyama-key-delete = Remove the selected point
umeyama-key-add = Add a point
umeyama-key-select = Select the next point, then the translation handle t, then the rotation handle s·R (Shift + n: the previous one)
umeyama-key-move = Move the selected point or t by 0.01, as a drag does; turn s·R by 0.5° (← →) or scale it by 0.01 (↑ ↓)
umeyama-selected = Point { $n } of { $count } selected, at ({ $x }, { $y }). Shift + arrows move it by 0.01; Delete removes it.
umeyama-selected-translation = Translation handle t selected, at ({ $x }, { $y }). Shift + arrows move it by 0.01.
umeyama-selected-rotation = Rotation handle s·R selected: angle { $angle }°, scale { $scale }. Shift + ← → turn it by 0.5°, Shift + ↑ ↓ scale it by 0.01.
umeyama-selected-none = No point selected ({ $count } points). Press n to select the next point, Shift + n the previous one.
umeyama-live = Fit: scale { $scale }, angle { $angle }°, rmse { $rmse }.
umeyama-ro-title = Estimate against the truth
umeyama-ro-estimate = Estimate
umeyama-ro-truth = Truth
umeyama-ro-scale = Scale s
umeyama-ro-angle = Angle (°)
umeyama-ro-tx = Translation tx
umeyama-ro-ty = Translation ty
umeyama-ro-rmse = rmse (truth column: σ√2)
umeyama-ro-note = The estimates are the numbers the CSV holds, to the last digit. The truth column of rmse is what the noise alone would give per point, σ√2.
umeyama-speed = One step every { $seconds } s
umeyama-step-overview-title = The whole fit
umeyama-step-overview-text = Y is the true similarity of X plus noise. The fit finds the s, R and t that bring X closest to Y in the least-squares sense; the green rings are s R X + t. Step on to see how.
umeyama-step-centroids-title = Centroids
umeyama-step-centroids-text = First the means of both sets: μx of X and μy of Y. The translation is settled last, from these two points.
umeyama-step-centred-title = Centred sets
umeyama-step-centred-text = Subtracting the means moves both sets onto the origin: Xc = X − μx and Yc = Y − μy. What is left to match is a rotation and a scale. var_x is the mean squared length of Xc.
umeyama-step-covariance-title = Cross-covariance
umeyama-step-covariance-text = C = Ycᵀ Xc / n sums, over the pairs, how each target lines up with its source. Its columns (teal arrows) are where C sends the two axes. A negative det C means Y looks mirrored against X.
umeyama-step-svd-title = SVD
umeyama-step-svd-text = C = U S Vᵀ: C turns each axis v_k of V (blue) into S_k u_k (orange). The best rotation is U Vᵀ, which turns every v_k onto its u_k.
umeyama-step-reflection-title = Reflection fix
umeyama-step-reflection-none = det(U Vᵀ) = +1: U Vᵀ is already a rotation, nothing to fix. Try the mirror preset to see the fix.
umeyama-step-reflection-fixed = det(U Vᵀ) = −1: U Vᵀ would be a reflection, which no rotation can be. The recipe negates U’s last column (the dashed red arrow is the old one), so R = U′Vᵀ is the rotation closest to C.
umeyama-step-scale-title = Scale
umeyama-step-scale-text = s = (S₁ + S₂) / var_x: how much bigger the targets spread than the sources, once turned. The circles have radius √var_x around μx and s √var_x around μy.
umeyama-step-scale-quirk = s = (S₁ + S₂) / var_x = { $recipe }. After a reflection fix Umeyama’s method would use S₁ − S₂ and get { $umeyama }; the recipe keeps the sum (its quirk).
umeyama-step-translation-title = Translation
umeyama-step-translation-text = t = μy − s R μx: the rotated and scaled sources (faint green) are carried onto the targets by the arrow from s R μx to μy.
umeyama-step-rmse-title = Residual error
umeyama-step-rmse-text = rmse = √(Σ |s R Xᵢ + t − Yᵢ|² / n), the red residuals. With noise σ on each coordinate it is about σ√2; with two points it is 0 whatever the noise.
umeyama-explain-what-title = What the recipe does
umeyama-explain-what = umeyama_align_2d.py draws n points X from numpy’s default_rng(seed), makes the targets Y = 1.3 R(35°) X + (0.4, −0.2) plus Gaussian noise of standard deviation σ, and recovers the scale, the rotation angle and the translation with Umeyama’s closed form. The CSV puts the estimates beside the true values; at the defaults (0.02 3 12) expect scale ≈ 1.3 and angle ≈ 35°.
umeyama-explain-steps-title = Why it works
umeyama-explain-steps = Removing the centroids separates the translation from the rest. The cross-covariance C collects how the centred targets line up with the centred sources; among all rotations, the one that maximises the alignment is U Vᵀ from the SVD of C. The scale is the ratio of the spread the rotation explains to the sources’ own spread, and the translation then matches the centroids.
umeyama-explain-reflection-title = Reflections
umeyama-explain-reflection = If the targets are a mirror image of the sources (the mirror preset), U Vᵀ is a reflection (det −1). A rotation cannot mirror, so the recipe flips U’s last column, giving the nearest proper rotation; the fit then stays poor, and rmse says so.
umeyama-explain-edit-title = Editing the run
umeyama-explain-edit = Points you add or drag, and a true similarity you change, are options of bsv umeyama-2d (--x, --scale, --angle, --tx, --ty, --mirror); without them the run is the Python recipe’s, byte for byte. The random numbers are drawn in the recipe’s order, so point i always gets the recipe’s noise for point i.
umeyama-explain-recipe-title = The recipe’s code (BSV original, MIT licence)
umeyama-explain-recipe = Input: sigma seed n (defaults 0.02 3 12). Output: umeyama_2d.csv with the estimated scale, rotation_deg, tx, ty, rmse and the true scale and rotation. Research and education only. Its fit, as the recipe writes it:
umeyama-code =
    def umeyama(X, Y):
        # X,Y: (n,2) corresponding points; estimate Y ≈ s R X + t
        mu_x = X.mean(axis=0); mu_y = Y.mean(axis=0)
        Xc = X - mu_x; Yc = Y - mu_y
        var_x = (Xc ** 2).sum() / len(X)
        cov = (Yc.T @ Xc) / len(X)
        U, S, Vt = np.linalg.svd(cov)
        R = U @ Vt
        if np.linalg.det(R) < 0:
            U[:, -1] *= -1
            R = U @ Vt
        s = (S.sum() / var_x) if var_x > 1e-12 else 1.0
        t = mu_y - s * R @ mu_x
        aligned = (s * (R @ X.T)).T + t
        rmse = float(np.sqrt(((aligned - Y) ** 2).sum() / len(X)))
        ang = math.degrees(math.atan2(R[1, 0], R[0, 0]))
        return s, ang, float(t[0]), float(t[1]), rmse
