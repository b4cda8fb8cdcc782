# 信号のページ: #/cubic-path, #/pid-step, #/trapezoid-profile。

## 共通
signals-readouts-title = 読み取り値
signals-png = グラフを保存（PNG）
signals-key-reset = レシピの既定値に戻す
signals-ax-t = 時刻 t
signals-unit-s = 秒
signals-computing = { $rows } 行を計算中… { $percent } %。終わるまで、グラフと読み取り値は前の結果のままです。

## 3 次経路
cubic-plots-title = 時間に対する q・qd・qdd
cubic-canvas-label = 3 次経路のグラフ：時間に対する位置・速度・加速度。位置のグラフで終点をドラッグできます。
cubic-drag-hint = 位置のグラフで終点（T, q1）をドラッグできます。グラフにポインタを重ねると、カーソル位置のサンプルを読み取れます。点は dt ごとのサンプルで、CSV の各行です。
cubic-overlay-quintic = 5 次（両端の加速度もゼロ）
cubic-overlay-trapezoid = 終了時刻が同じ台形
cubic-series-quintic = 5 次
cubic-series-trapezoid = 台形
cubic-series-cubic = 3 次（レシピ）
cubic-ax-q = 角度 q
cubic-ax-qd = 速度 qd
cubic-ax-qdd = 加速度 qdd
cubic-unit-rad = rad
cubic-unit-rad-s = rad/秒
cubic-unit-rad-s2 = rad/秒²
cubic-ro-peak-v = 最大速度（rad/秒）
cubic-ro-peak-v-t = そのときの t（秒）
cubic-ro-peak-a = 最大加速度（rad/秒²）
cubic-ro-peak-a-t = そのときの t（秒）
cubic-ro-a0 = 係数 a0（rad）
cubic-ro-a1 = 係数 a1（rad/秒）
cubic-ro-a2 = 係数 a2（rad/秒²）
cubic-ro-a3 = 係数 a3（rad/秒³）
cubic-ro-rows = サンプル数（CSV の行数）
cubic-ro-cursor-t = カーソル：t（秒）
cubic-ro-cursor-q = カーソル：q（rad）
cubic-ro-cursor-qd = カーソル：qd（rad/秒）
cubic-ro-cursor-qdd = カーソル：qdd（rad/秒²）
cubic-live = q1 { $q1 } rad、T { $T } 秒：最大速度 { $peak } rad/秒。
cubic-key-q1 = 終了角 q1 を 0.01 rad 上げ下げ（Shift で 0.1）
cubic-key-t = 所要時間 T を 0.01 秒短く・長く（Shift で 0.1）
cubic-explain-what-title = 3 次式
cubic-explain-what = q(t) = a0 + a1·t + a2·t² + a3·t³ に q(0) = q0、q(T) = q1、両端の速度ゼロを課すと、a0 = q0、a1 = 0、a2 = 3·(q1 − q0)/T²、a3 = −2·(q1 − q0)/T³ になります。速度は放物線で、動作の中間で最大 1.5·(q1 − q0)/T。加速度は 6·(q1 − q0)/T² からその符号反転まで直線的に変わるので、両端で跳びます。5 次式は加速度もゼロで始まりゼロで終わりますが、そのぶん最大速度が高くなります（1.875·(q1 − q0)/T）。台形は一定の加速と減速のあいだを一定速度で進みます。
cubic-explain-input-title = 入力と出力
cubic-explain-input = q0, q1 は rad、T と dt は秒（既定値 0 1.2 1.0 0.02）。出力は t_s, q, qd, qdd の列をもつ cubic_path.csv です。
cubic-explain-steps-title = 手順
cubic-explain-steps = 1. スクリプトを保存します。2. 実行: python cubic_joint_path.py 0 1.2 1.0 0.02 3. 両端で qd ≈ 0 であることを確かめます。
cubic-explain-expected-title = 期待される結果
cubic-explain-expected = およそ T/dt + 1 行。q0 から q1 へなめらかに動く q。

## PID ステップ応答
pid-plots-title = 出力 y・目標値 r・操作量 u
pid-canvas-label = PID ステップ応答のグラフ：上は目標値 r と出力 y、下は操作量 u（横軸は時間）。
pid-ghost-note = 灰色の曲線は直前のゲインです。次に値を変えるまで残るので、2 つの調整を見比べられます。
pid-ax-y = 出力 y
pid-ax-u = 操作量 u
pid-series-y = 出力 y
pid-series-r = 目標値 r
pid-series-u = 操作量 u
pid-series-ghost-y = 直前のゲインの y
pid-series-ghost-u = 直前のゲインの u
pid-ro-rise = 立ち上がり時間 10〜90 %（秒）
pid-ro-overshoot = オーバーシュート（%）
pid-ro-settling = 整定時間 ±2 %（秒）
pid-ro-sse = 定常偏差 r − y（最終行）
pid-ro-peak-u = 操作量 u の最大値
pid-ro-peak-u-t = そのときの t（秒）
pid-ro-final-y = 最終の出力 y
pid-ro-cursor-t = カーソル：t（秒）
pid-ro-cursor-r = カーソル：目標値 r
pid-ro-cursor-y = カーソル：出力 y
pid-ro-cursor-u = カーソル：操作量 u
pid-ro-none = 未到達
pid-ro-note = CSV の各行から補間せずに読み取った値です。時刻は CSV の t 列（k 行目は t = k × 0.05 秒、y はそのステップ後の値）。
pid-live = 立ち上がり時間 { $rise }、オーバーシュート { $overshoot }、整定時間 { $settling }。
pid-live-seconds = { $value } 秒
pid-live-percent = { $value } %
pid-key-kp = Kp を 0.05 上げ下げ（Shift で 0.5）
pid-explain-gains-title = 各ゲインの働き
pid-explain-gains = Kp はいまの偏差に比例して押します。大きくすると速く立ち上がりますが、行き過ぎ、ある点を超えると振動します。Ki は偏差を時間で積み上げ、P 制御だけでは残るオフセットを消しますが、そのぶんオーバーシュートが増え整定が遅くなります（ワインドアップ）。Kd は偏差の変化の速さに反応して行き過ぎを抑えますが、ステップ入力では最初のサンプルで u に大きな「キック」を生みます。
pid-explain-plant-title = プラント
pid-explain-plant = 時定数 τ の 1 次遅れを dt = 0.05 秒ごとに進めます：y ← y + a·(u − y)、a = dt / (τ + dt)。τ = 0 なら出力は u にすぐ追従します。目標値は単位ステップ r = 1 です。
pid-explain-toy-title = これが「おもちゃ」である理由
pid-explain-toy = u に上限がなく（実際のアクチュエータは飽和します）、微分は偏差そのものに掛かり（フィルタがないので、ノイズやステップ自体がスパイクを生みます）、偏差が残るかぎり積分は増え続け（アンチワインドアップなし）、ノイズも遅れも外乱もありません。
pid-explain-real-title = 実際の制御器が加えるもの
pid-explain-real = アンチワインドアップ付きの出力制限、偏差ではなく計測値に掛けるフィルタ付き微分、目標値の重み付けやランプ、リアルタイム保証のある一定の制御周期、手動と自動のバンプレス切り替え、そして安全の仕組み：ループに頼らない制限、ウォッチドッグ、非常停止。
pid-explain-input-title = 入力と出力
pid-explain-input = Kp Ki Kd tau steps（既定値 1.2 0.4 0.05 0.8 80）。出力は t, r, y, u, e の列をもつ pid_step.csv です。
pid-explain-steps-title = 手順
pid-explain-steps = 1. スクリプトを保存します。2. 実行: python pid_step_response.py 3. 最終の y を目標値 1.0 と比べます。
pid-explain-expected-title = 期待される結果
pid-explain-expected = 標準ライブラリだけで、y が 1.0 に向かって上がります。

## 台形プロファイル
trap-plots-title = 時間に対する位置 s・速度 v・加速度 a
trap-canvas-label = 台形プロファイルのグラフ：時間に対する位置・速度・加速度。3 つの区間は色分けしています。速度のグラフで vmax と加速の角をドラッグできます。
trap-drag-hint = 速度のグラフで、破線上のハンドルをドラッグすると vmax が、加速の角をドラッグすると amax（その傾き）が変わります。
trap-triangle = 三角形：距離が短すぎて vmax に届かないため、加速が終わるとすぐに減速します。最大速度は vmax より低くなります。
trap-series-profile = レシピのサンプル
trap-ax-s = 位置 s
trap-ax-v = 速度 v
trap-ax-a = 加速度 a
trap-phase-accel = 加速
trap-phase-cruise = 等速
trap-phase-brake = 減速
trap-shape-triangle = 三角形（vmax に届かない）
trap-shape-trapezoid = 台形
trap-ro-shape = 形
trap-ro-t-acc = 加速時間 t_acc（秒）
trap-ro-t-flat = 等速時間 t_flat（秒）
trap-ro-t-total = 全体の時間 t_total（秒）
trap-ro-v-peak = 実際に届いた最大速度
trap-ro-final-s = 最終行の位置
trap-ro-rows = サンプル数（CSV の行数）
trap-ro-cursor-t = カーソル：t（秒）
trap-ro-cursor-s = カーソル：位置 s
trap-ro-cursor-v = カーソル：速度 v
trap-ro-cursor-a = カーソル：加速度 a
trap-live = { $shape }：動作は { $total } 秒で、最大速度は { $peak }。
trap-key-vmax = vmax を 0.01 上げ下げ（Shift で 0.1）
trap-key-amax = amax を 0.01 下げる・上げる（Shift で 0.1）
trap-explain-what-title = プロファイル
trap-explain-what = amax で加速して vmax に達し（t_acc = vmax / amax、その間に amax·t_acc²/2 進む）、vmax で等速に進み、amax で減速して距離ちょうどで止まります。距離が amax·t_acc² より短いと等速の余地がなく、√(距離 / amax) で折り返す三角形になり、最大速度は vmax に届きません。速度は連続ですが、加速度は区間が変わるたびに跳ぶ（躍度が無限大）ので、実際の駆動系は角を丸めます（S 字カーブ）。
trap-explain-input-title = 入力と出力
trap-explain-input = distance vmax amax dt（既定値 1.0 0.5 1.0 0.01）。符号は無視されます。出力は t, s, v, a の列をもつ trap_profile.csv です。
trap-explain-steps-title = 手順
trap-explain-steps = 1. スクリプトを保存します。2. 実行: python trapezoid_velocity_profile.py 3. s が距離の近くで終わることを確かめます。
trap-explain-expected-title = 期待される結果
trap-explain-expected = CSV は加速、（あれば）等速、減速の区間をふくみます。
pid-short = 目標値 r に届きません（誤差 { $error }）。比例動作だけでは定常偏差が残り、Ki = { $ki } ではこの実行内に消せません。積分動作を強めましょう。
pid-tuned = 調整済みのゲインを試す
