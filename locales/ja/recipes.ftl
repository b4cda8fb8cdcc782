# 12 のレシピ：タイトル、1 行の説明、各位置引数（`-arg-<name>`）とオプション
# （`-flag-<name>`）のラベル。名前は各モジュールの `INFO` に合わせる。

## pendulum-energy
recipe-pendulum-energy-title = MuJoCo で振り子のエネルギードリフトを記録する
recipe-pendulum-energy-blurb = 減衰のある振り子をシミュレーションし、運動・位置・全エネルギーの時間変化を書き出します。減衰があればドリフトは起きて当然で、それを CSV で確かめるのが目的です。
recipe-pendulum-energy-arg-duration_s = シミュレーション時間（秒）
recipe-pendulum-energy-flag-damping = ヒンジの減衰係数 b（N·m·s/rad）
recipe-pendulum-energy-flag-angle-deg = 真下からの初期角度（度）
recipe-pendulum-energy-flag-timestep = 積分の時間刻み h（秒）
recipe-pendulum-energy-flag-length = カプセルの長さ L（m）
recipe-pendulum-energy-flag-mass = カプセルの質量 m（kg）
recipe-pendulum-energy-flag-radius = カプセルの半径 r（m）
recipe-pendulum-energy-flag-integrator = 積分法：euler（MuJoCo の既定）または rk4

## ik-workspace
recipe-ik-workspace-title = 平面 2 リンクの IK 作業領域をサンプリングする
recipe-ik-workspace-blurb = 平面を格子に区切って到達できるセルに印を付け、肘下げ解の IK と FK 誤差（mm）を記録します。
recipe-ik-workspace-arg-L1 = リンク 1 の長さ L1（m）
recipe-ik-workspace-arg-L2 = リンク 2 の長さ L2（m）
recipe-ik-workspace-arg-half_mm = 格子の半幅（mm）
recipe-ik-workspace-arg-step_mm = 格子の間隔（mm）

## traj-resample
recipe-traj-resample-title = 関節軌道を一定の dt でリサンプリングする
recipe-traj-resample-blurb = q の各列を線形補間して、等間隔の時間グリッドに載せ替えます。既定の入力は、ラベル付きの合成サンプルです。
recipe-traj-resample-arg-csv_path = 軌道の CSV（t_s, q1, q2, …）。指定しなければラベル付きサンプル
recipe-traj-resample-arg-dt = 時間刻み dt（秒）

## dh-fk
recipe-dh-fk-title = 短い DH チェーンの順運動学
recipe-dh-fk-blurb = 固定の 3R デモチェーンに修正 DH 変換を順に掛け、各フレームの原点と XYZ の RPY を書き出します。
recipe-dh-fk-arg-angles = 関節角 q1,q2,q3（rad、カンマ区切り）

## jacobian-2r
recipe-jacobian-2r-title = 平面 2R のヤコビアンと可操作度のスイープ
recipe-jacobian-2r-blurb = q2 を固定して q1 を動かし、det(J)、吉川の可操作度、特異値を書き出します。シミュレーションを理解するための演習です。
recipe-jacobian-2r-arg-L1 = リンク 1 の長さ L1（m）
recipe-jacobian-2r-arg-L2 = リンク 2 の長さ L2（m）
recipe-jacobian-2r-arg-q1_start = q1 の開始値（rad）
recipe-jacobian-2r-arg-q1_stop = q1 の終了値（この値を含む、rad）
recipe-jacobian-2r-arg-q1_step = q1 の刻み（rad）
recipe-jacobian-2r-arg-q2 = q2（固定値、rad）

## cubic-path
recipe-cubic-path-title = 両端の速度がゼロの 3 次関節経路
recipe-cubic-path-blurb = q0 から q1 へ、定番の 3 次補間 q(t) を作ります。リアルタイムの動作計画器ではありません。
recipe-cubic-path-arg-q0 = 開始角 q0（rad）
recipe-cubic-path-arg-q1 = 終了角 q1（rad）
recipe-cubic-path-arg-T = 所要時間 T（秒）
recipe-cubic-path-arg-dt = 時間刻み dt（秒）

## se3-relative
recipe-se3-relative-title = XYZ+RPY で表した 2 つのフレームの相対 SE(3) 姿勢
recipe-se3-relative-blurb = T_A と T_B を作り、T_A⁻¹ T_B を xyz と rpy で書き出します。教育用です。
recipe-se3-relative-arg-ax = フレーム A：x（m）
recipe-se3-relative-arg-ay = フレーム A：y（m）
recipe-se3-relative-arg-az = フレーム A：z（m）
recipe-se3-relative-arg-ar = フレーム A：ロール（rad）
recipe-se3-relative-arg-ap = フレーム A：ピッチ（rad）
recipe-se3-relative-arg-aw = フレーム A：ヨー（rad）
recipe-se3-relative-arg-bx = フレーム B：x（m）
recipe-se3-relative-arg-by = フレーム B：y（m）
recipe-se3-relative-arg-bz = フレーム B：z（m）
recipe-se3-relative-arg-br = フレーム B：ロール（rad）
recipe-se3-relative-arg-bp = フレーム B：ピッチ（rad）
recipe-se3-relative-arg-bw = フレーム B：ヨー（rad）

## rrt-2d
recipe-rrt-2d-title = 長方形の障害物を避ける 2D の簡易 RRT
recipe-rrt-2d-blurb = 単位正方形の中で、スタートからゴールへ小さな RRT を伸ばします。学習用の簡易な計画器で、実際のロボットや安全性の検討には使えません。
recipe-rrt-2d-arg-seed = 乱数シード
recipe-rrt-2d-arg-max_iter = 最大反復回数
recipe-rrt-2d-flag-obstacle = 障害物の箱 x0,y0,x1,y1
recipe-rrt-2d-flag-start = スタート x,y
recipe-rrt-2d-flag-goal = ゴール x,y
recipe-rrt-2d-flag-step = 1 回に伸ばす長さ
recipe-rrt-2d-flag-goal-bias = ゴールバイアス
recipe-rrt-2d-flag-goal-tol = ゴール判定の距離
recipe-rrt-2d-flag-goal-x = ゴールの x 座標（0〜1）
recipe-rrt-2d-flag-goal-y = ゴールの y 座標（0〜1）

## pid-step
recipe-pid-step-title = 離散 PID のステップ応答（簡易プラント）
recipe-pid-step-blurb = 1 次遅れのプラントに対する閉ループのステップ応答です。シミュレーションを理解するためのもので、実際の制御器ではありません。
recipe-pid-step-arg-Kp = 比例ゲイン Kp
recipe-pid-step-arg-Ki = 積分ゲイン Ki（1/s）
recipe-pid-step-arg-Kd = 微分ゲイン Kd（s）
recipe-pid-step-arg-tau = プラントの時定数 τ（秒）
recipe-pid-step-arg-steps = ステップ数（1 ステップ 0.05 秒）

## manip-grid
recipe-manip-grid-title = 平面 2R の可操作度グリッド
recipe-manip-grid-blurb = 関節空間の格子上で |det J| をサンプリングします。
recipe-manip-grid-arg-L1 = リンク 1 の長さ L1（m）
recipe-manip-grid-arg-L2 = リンク 2 の長さ L2（m）
recipe-manip-grid-arg-n = 格子の大きさ n（n × n 通りの関節角）

## trapezoid-profile
recipe-trapezoid-profile-title = 台形速度プロファイル
recipe-trapezoid-profile-blurb = 加速・等速・減速からなる 1 軸の移動です。ロボットを駆動するためのものではありません。
recipe-trapezoid-profile-arg-distance = 移動距離
recipe-trapezoid-profile-arg-vmax = 速度の上限 vmax
recipe-trapezoid-profile-arg-amax = 加速度の上限 amax
recipe-trapezoid-profile-arg-dt = 時間刻み dt（秒）

## umeyama-2d
recipe-umeyama-2d-title = Umeyama 法による 2D 相似変換の推定（簡易版）
recipe-umeyama-2d-blurb = ノイズのある対応点から、スケール・回転・並進を推定します。
recipe-umeyama-2d-arg-sigma = ノイズの標準偏差 σ
recipe-umeyama-2d-arg-seed = 乱数シード
recipe-umeyama-2d-arg-n = 対応点の組数 n
recipe-umeyama-2d-flag-scale = 真のスケール s
recipe-umeyama-2d-flag-angle = 真の回転角（°）
recipe-umeyama-2d-flag-tx = 真の並進 tx
recipe-umeyama-2d-flag-ty = 真の並進 ty
recipe-umeyama-2d-flag-mirror = 先に X を鏡映
recipe-umeyama-2d-flag-x = 元の点群 X（x,y;x,y;…）

## 引数のヒント：各引数の制限を言葉で（`ArgSpec::hint_id`）。数値はカーネルの定数と同じ
## （一致することをテストで確かめている）。
recipe-pendulum-energy-hint-duration_s = 秒、0 より大きい値。時間刻みで割り切れるステップ数だけ計算し、ステップ数は 1〜1,000,000 です（既定の 0.002 秒刻みなら 2,000 秒まで）。
recipe-pendulum-energy-hint-damping = 0 以上（N·m·s/rad）、上限なし。0 にすると、物体の本当のエネルギーは（積分誤差を除いて）一定に保たれます。
recipe-pendulum-energy-hint-angle-deg = 真下にぶら下がった状態からの角度（度）。任意の数値。
recipe-pendulum-energy-hint-timestep = 秒、0 より大きい値、上限なし。小さくするほど行が増えます。ステップ数は最大 1,000,000 です。
recipe-pendulum-energy-hint-length = メートル、0 より大きい値、上限なし。
recipe-pendulum-energy-hint-mass = キログラム、0 より大きい値、上限なし。
recipe-pendulum-energy-hint-radius = メートル、0 より大きい値、上限なし。
recipe-pendulum-energy-hint-integrator = euler はレシピと同じ MuJoCo の既定（半陰的オイラー法、減衰は陰的に扱う）、rk4 は古典的な 4 次のルンゲ・クッタ法です。
recipe-2r-hint-L1 = メートル、0.000001〜10。
recipe-2r-hint-L2 = メートル、0.000001〜10。
recipe-ik-workspace-hint-half_mm = ミリメートル、0〜1,000,000。
recipe-ik-workspace-hint-step_mm = ミリメートル、0 より大きい値。格子は最大 1,001 × 1,001 セルです（たとえば ±500 mm を 1 mm 刻み）。
recipe-traj-resample-hint-csv_path = t_s 列（秒、常に増加）と関節ごとの列をもつ CSV。note 列は取り除かれます。128 MiB まで読み込めます。
recipe-traj-resample-hint-dt = 秒、0 より大きい値。出力は最大 20,000,000 セル（行数 × 関節数）です。
recipe-dh-fk-hint-angles = 3 つの角度（ラジアン）をカンマで区切って入力します。
recipe-jacobian-2r-hint-q1_start = ラジアン、−1,000〜1,000。
recipe-jacobian-2r-hint-q1_stop = ラジアン、q1 の開始値以上、1,000 以下。
recipe-jacobian-2r-hint-q1_step = ラジアン、0 より大きい値。サンプル数は最大 1,000,000 です。
recipe-jacobian-2r-hint-q2 = ラジアン、−1,000〜1,000。
recipe-cubic-path-hint-q0 = ラジアン、−1,000,000,000〜1,000,000,000。
recipe-cubic-path-hint-q1 = ラジアン、−1,000,000,000〜1,000,000,000。
recipe-cubic-path-hint-T = 秒、0.000000001〜1,000,000,000。
recipe-cubic-path-hint-dt = 秒、0 より大きい値。最大 1,000,000 行です（T ÷ dt + 1）。
recipe-se3-relative-hint-position = メートル。任意の数値。
recipe-se3-relative-hint-angle = 度ではなくラジアン。任意の数値。
recipe-hint-seed = 0〜9,223,372,036,854,775,807（2⁶³ − 1）の整数（numpy の default_rng が受け付ける範囲）。同じシードなら Python と同じ乱数になります。
recipe-rrt-2d-hint-max_iter = 0〜1,000,000 の整数。ゴールに届いた時点で木の成長は止まります。100 万回の反復でも 1 秒ほどで終わります。
recipe-rrt-2d-hint-goal-x = 0〜1（単位正方形の中）。「ゴール」の x 座標と同じです。この指定では箱の中のゴールも受け付けますが、決して届きません。
recipe-rrt-2d-hint-obstacle = 0〜1 の 4 つの数 x0,y0,x1,y1（x0 ≤ x1、y0 ≤ y1）で箱を 1 つ表します（辺の上も箱の内側です）。箱ごとに 1 回ずつ、32 個まで指定できます。指定した箱がレシピの箱の代わりになり、「none」で箱のない正方形になります。
recipe-rrt-2d-hint-start = 0〜1 の 2 つの数 x,y。どの箱の外側にも置いてください。木の根になります。
recipe-rrt-2d-hint-goal = 0〜1 の 2 つの数 x,y。どの箱の外側にも置いてください。
recipe-rrt-2d-hint-step = 0.001〜1。1 回の反復で伸ばす最大の長さです（レシピの STEP）。
recipe-rrt-2d-hint-goal-bias = 0〜1。ゴールそのものをサンプルにする確率です（レシピの GOAL_BIAS）。
recipe-rrt-2d-hint-goal-tol = 0.001〜1.5。新しいノードがゴールからこの距離未満で、ゴールまでの線分がふさがれていなければ探索を終えます（レシピの GOAL_TOL）。
recipe-rrt-2d-hint-goal-y = 0〜1（単位正方形の中）。「ゴール」の y 座標と同じです。この指定では箱の中のゴールも受け付けますが、決して届きません。
recipe-pid-step-hint-Kp = 任意の数値（単位なし）。大きすぎるゲインや負のゲインでは、ループが不安定になります。
recipe-pid-step-hint-Ki = 任意の数値（1/秒）。
recipe-pid-step-hint-Kd = 任意の数値（秒）。
recipe-pid-step-hint-tau = 秒、0〜1,000,000。
recipe-pid-step-hint-steps = 0〜1,000,000 の整数（1 ステップ 0.05 秒なので 50,000 秒まで）。
recipe-manip-grid-hint-n = 1〜1,024 の整数。n × n 行なので、最大 1,048,576 行です。
recipe-trapezoid-profile-hint-distance = −1,000,000,000〜1,000,000,000 の任意の数値。符号は無視されます。
recipe-trapezoid-profile-hint-vmax = 0 以外で、大きさは 0.000000001〜1,000,000,000。符号は無視されます。
recipe-trapezoid-profile-hint-amax = 0 以外で、大きさは 0.000000001〜1,000,000,000。符号は無視されます。
recipe-trapezoid-profile-hint-dt = 秒、0 より大きい値。最大 1,000,000 行です（移動時間 ÷ dt）。
recipe-umeyama-2d-hint-sigma = 0 以上、上限なし（0 ならノイズなしで、ぴったり一致します）。
recipe-umeyama-2d-hint-n = 2〜100,000 の整数。
recipe-umeyama-2d-hint-scale = 0 より大きく 1,000 以下（レシピの値は 1.3）。
recipe-umeyama-2d-hint-angle = −360〜360 度（レシピの値は 35）。
recipe-umeyama-2d-hint-t = −1,000〜1,000（レシピの t は (0.4, −0.2)）。
recipe-umeyama-2d-hint-mirror = yes を選ぶと、相似変換の前に X を鏡映（y → −y）します。どの回転でも合わせられないので、鏡映の補正が現れます。
recipe-umeyama-2d-hint-x = n 個の点を x,y の組にしてセミコロンで区切ります。各座標は −1,000〜1,000。空欄ならレシピの乱数の点です。

## 癖：Python のレシピが何も言わない、奇妙な、または異常終了するところでの扱い
## （`RecipeInfo::quirks_id`）。
recipe-pendulum-energy-quirks = エネルギーは、シミュレーションしているカプセルではなく、距離 L の先端にある質量 m の質点として計算しています。そのため total はこの物体の本当の力学的エネルギーではなく、減衰がなくても変化します。pe には各ステップの前の先端の高さ（MuJoCo が最後に位置を計算した時点）を使い、時刻の列は i·h ですが、状態は i 番目のステップの後のものです。
recipe-ik-workspace-quirks = レシピにない制限として、リンク長は 0.000001〜10 m（Python では 0 で 0 除算になります）、格子は最大 1,001 × 1,001 セルです。届く範囲の輪のちょうど縁にあるセルは、Python と同じく届くものとして扱います（|c2| ≤ 1）。
recipe-traj-resample-quirks = サンプル（またはあなたのファイル）の note 列は、出力から取り除かれます。時刻は行ごとに必ず増えていく必要があります。Python のレシピはこれを確かめず、np.interp は警告なしにおかしな値を返します。このページではそのようなファイルを受け付けず、時刻が増えていない最初の行を示します。
recipe-dh-fk-quirks = このチェーンは、古典的な（標準）DH ではなく修正 DH（Craig の流儀）のパラメータを使います。同じ 4 つの数値を古典 DH のツールに入れると、別のフレームになります。ベースの行は文字どおりの 0 で書き出され、参照実装が負のゼロを計算するところ（atan2(−0.0, 1) のピッチ）には −0.0 が現れます。値は 0 と同じで、Python の表示に合わせているだけです。
recipe-jacobian-2r-quirks = q1 の終了値は含まれます（レシピは 1e-12 を足しています）。終了値が開始値より小さい場合や刻みが 0 の場合、Python のレシピは空のスイープで異常終了しますが、ここでは引数を示して受け付けません。サンプル数は最大 1,000,000 です。
recipe-cubic-path-quirks = T と dt は、レシピ自身が確かめるとおり 0 より大きくなければなりません。最後のサンプルは T を超えない dt の最後の倍数の時刻なので、dt が T を割り切らないと、経路は q1 の手前で終わります。
recipe-se3-relative-quirks = Python のレシピの説明には角度は「度」とありますが、コードでは値をそのまま cos と sin に渡しているので、実際にはラジアンです（0.2 rad ≈ 11.5°）。30° のつもりで 30 と入力すると、30 rad 回ることになります。角度は回転行列から読み戻すので、pitch は −π/2〜π/2 の範囲になり、pitch が ±π/2（ジンバルロック）のときは roll を 0 にします。
recipe-rrt-2d-quirks = 線分の衝突判定は、等間隔の 12 点でしか行いません。そのため、線分が箱の角をかすめて通り抜けることがあります。max_iter 回の反復でゴールに届かなかった場合（ゴールを箱の中に置いてみてください）、rrt_path.csv はヘッダーだけになり、経路長は nan と表示されます。
recipe-pid-step-quirks = 目標値と dt = 0.05 秒はレシピで固定されています。負のステップ数は Python では空の表になりますが、ここでは受け付けません。不安定なループ（大きすぎるゲインや負のゲイン）では値が増え続け、Python と同じように inf、そして nan と表示されます。そうなったときはページが警告します。
recipe-manip-grid-quirks = Python のファイル名は manip_ellipse_2r.py で、出力も manip_ellipse.csv ですが、楕円は計算していません。detJ は det J、manip は |det J|（可操作度楕円の面積の倍率）です。楕円そのものは、平面 2 リンク IK プレイグラウンドで描いています。
recipe-trapezoid-profile-quirks = 時刻は t ≤ t_total のあいだ t += dt の足し算を繰り返して進むので、丸め誤差が積み重なり、それが行数を決めます。各行の時刻は round(t, 5) で表示されます。三角形の場合、減速部分では届かなかった vmax から求めた d_acc をそのまま使うため、位置が行き過ぎます。0.2 1.0 2.0 では、表は s = 0.2 ではなく s ≈ 0.35 で終わります。
recipe-umeyama-2d-quirks = SVD の結果が鏡映（det R < 0）になったとき、レシピは Umeyama の方法どおり U の列の符号を反転しますが、スケールは (S1 + S2) / var_x のままにします。Umeyama の方法では S1 − S2 を使います。影響が出るのは、点の配置がほぼ退化しているか、ノイズがとても大きい場合だけです。
