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
recipe-manip-grid-blurb = 関節空間の格子上で |det J| をサンプリングします。平面 2 リンク IK プレイグラウンドと合わせて使えます。
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
