# ドリル一覧のページ（#/drills、src/ui/pages/drills/）。レシピのタイトル・説明・引数のラベル
# （recipes.ftl）とカーネルのエラー（errors.ftl）を除く、ページに表示する文字列のすべて。

drills-lede = ドリルを選び、値を決めて実行しましょう。ダウンロードするファイルは、同じ引数で実行した Python のレシピとファイル名・列・数値まで同じです。結果の下にあるコマンドを使えば、同じ結果を手元で再現できます。データがこのページの外に送られることはありません。

## フォーム
drills-picker-label = ドリル
drills-run = 実行
drills-reset = 既定値に戻す
drills-file-using-sample = 入力：内蔵のラベル付きサンプル（{ $name }、{ $rows } 行）
drills-file-using = 入力：{ $name }（{ $size }）
drills-file-using-rows = 入力：{ $name }（{ $size }、{ $rows } 行、関節の列が { $joints } 個）
drills-file-missing = このリンクではファイル「{ $name }」が使われていました。実行するには、もう一度開いてください。ファイルは手元のコンピューターから外に出ないため、リンクには含められません。
drills-file-too-large = 「{ $name }」は { $size } あり、このドリルで読み込める上限の { $limit } を超えているため、開きませんでした。
drills-file-unreadable = 「{ $name }」を読み込めませんでした（{ $reason }）。
drills-reading = { $name } を読み込んでいます…

## 「実行」の横に表示する状態
drills-running = 実行中…
drills-large = 計算量の多い実行です。「実行」ボタン（または Enter）を押すと計算します。実行中はページが応答しなくなり、最大のサイズでは数秒かかります。
drills-invalid = 赤で示した値を直してから、もう一度実行してください。
drills-done = { $ms } ミリ秒で完了しました。
drills-failed = ドリルはエラーで止まりました。理由はメッセージを見てください。
drills-code-failed = ドリルを実行するコードを読み込めませんでした。接続を確認して、もう一度「実行」を押してください。

## ページを開いたリンクについてのお知らせ
drills-url-unknown-recipe = このリンクのドリル「{ $id }」は存在しないため、代わりに「{ $title }」を表示しています。

## 結果
drills-output-title = 結果
drills-output-empty = まだ何も計算していません。「実行」を押すか、どれかの欄で Enter を押してください。
drills-stale = この結果を計算したあとで値が変わりました。「実行」（または Enter）で更新してください。下のファイルとコマンドは、互いに対応したままです。
drills-summary-label = レシピが表示する行
drills-file-size = { $rows_text } 行、{ $columns } 列、{ $size }
drills-preview-label = { $file } のプレビュー
drills-preview-empty = ヘッダーだけです。この実行ではデータ行が書き出されませんでした。
drills-preview-all = ファイル全体（{ $rows_text } 行）を表示しています。
drills-preview-some = { $rows_text } 行のうち、最初の { $shown } 行を表示しています。ダウンロードしたファイルには全行が入っています。
drills-preview-columns = { $columns } 列のうち { $shown } 列を表示しています。

## 解説
drills-about-title = 何を計算するのか
drills-quirks-title = Python のレシピの癖（あえてそのまま再現しています）
drills-about-parity = 数値は、bsv コマンドと同じ Rust のコードがブラウザの中で計算し、Python と同じ書き方（往復で値が変わらない最短の桁数）で書き出します。そのため、Python のレシピが出力した CSV と diff を取っても差は出ません。

drills-about-pendulum-energy = 減衰のある振り子（ヒンジに付いたカプセル）を、MuJoCo とまったく同じ方法で int(時間 ÷ 時間刻み) 回ステップさせます。各行には角度 θ、角速度 ω と 3 つのエネルギー、ke = ½ m (L ω)²、pe = m g (z + L)、total = ke + pe が入ります。減衰があれば total は減っていくはずです。表示されるドリフトは max(total) − min(total) です。

drills-about-ik-workspace = 根元のまわり ±half_mm の範囲を、step_mm 間隔の正方格子で覆います。各セル (x, y) について、c2 = (x² + y² − L1² − L2²) / (2 L1 L2) が −1〜1 に入れば 2 リンクアームの手先が届きます。届くセルには肘下げの解 q2 = acos c2、q1 = atan2(y, x) − atan2(L2 sin q2, L1 + L2 cos q2) と、その解の順運動学とセルとの距離 fk_err_mm（丸め誤差だけ）を記録します。届かないセルでは角度の欄は空になります。

drills-about-traj-resample = 時刻の列 t_s と関節ごとの列をもつ軌道を読み込み、各関節を等間隔の時刻 t0, t0 + dt, … 最後の時刻まで線形補間します（numpy の interp）。ファイルを指定しない場合、レシピはまずラベル付きの合成サンプルを書き出し、それをリサンプリングするので、ファイルが 2 つできます。

drills-about-dh-fk = 3 関節の固定されたデモ用チェーンの順運動学です。リンクごとに修正 DH 変換（関節角 θ = q ＋ リンクのオフセット）を直前のフレームに掛けていき、ベースフレームから順に、各フレームの原点 x, y, z と roll, pitch, yaw（XYZ 固定角）を書き出します。

drills-about-jacobian-2r = q2 を固定したまま、q1 を開始値から終了値（この値を含む）まで刻みごとに動かします。各行には手先の位置、det J = L1 L2 sin q2、吉川の可操作度 w = √det(J Jᵀ)、ヤコビ行列の特異値 σ_min, σ_max が入ります。平面 2R アームではこれらは q2 だけで決まるので、（丸め誤差を除いて）どの行も同じ値になります。アーム全体を回しても、動きやすさは変わらないということです。

drills-about-cubic-path = 3 次式 q(t) = q0 + a2 t² + a3 t³（a2 = 3 (q1 − q0) / T²、a3 = −2 (q1 − q0) / T³）は、静止した状態から始まり静止した状態で終わるように、時間 T で q0 から q1 まで動きます。0 から T まで dt ごとに、速度 qd と加速度 qdd とともにサンプリングします。加速度は両端で 0 にならず、動き始めと止まるときに跳びます。より滑らかな計画器が 5 次多項式を使うのはこのためです。

drills-about-se3-relative = 2 つの姿勢（x, y, z と roll, pitch, yaw、R = Rz(yaw) Ry(pitch) Rx(roll)）から同次変換 T_A と T_B を作り、T_A⁻¹ T_B を書き出します。フレーム A から見て、フレーム B がどこにあり、どう回っているかを表します。

drills-about-rrt-2d = 単位正方形の中で、(0.1, 0.1) からゴールに向かって、箱形の障害物 [0.35, 0.65] × [0.25, 0.75] をよけながら RRT（高速探索ランダム木）を伸ばします。毎回 numpy の default_rng(seed) で点を 1 つ引き（10 回に 1 回はゴールそのもの）、いちばん近いノードからその点に向かって 0.05 進み、正方形の中にとどまって箱に触れなければその一歩を採用します。ゴールから 0.06 以内のノードができたら終わりです。rrt_path.csv はスタートからゴールまでの経路、rrt_nodes.csv は親の番号つきの木全体です。

drills-about-pid-step = 1 次遅れのプラント y ← y + a (u − y)（a = dt / (τ + dt)、dt = 0.05 秒）のまわりに離散 PID 制御器でループを閉じ、目標値 r = 1 のステップ入力を与えます。各ステップで誤差 e = r − y、その積算と変化、指令 u = Kp e + Ki ∫e + Kd de/dt、新しい出力 y を計算します。表示される final_y を見れば、ループがどこまで目標に近づいたかがわかります。Ki を大きくすると残りの誤差が消え、Kp を大きくするとオーバーシュートが出ます。ループが不安定になるゲインでは値が増え続け、Python と同じように最後は inf、そして nan と表示されます。

drills-about-manip-grid = q1 と q2 をそれぞれ −π〜π の範囲で n × n の格子に区切り、平面 2R アームの det J = L1 L2 sin q2 を計算して、|det J| の最大値とその位置を表示します。アームは肘が直角のときにいちばん動きやすく、伸びきったときや折り返したときに特異（det J = 0）になります。

drills-about-trapezoid-profile = |distance| の移動を、amax で加速し、vmax で等速移動し、amax で減速する（vmax に届かなければ三角形になる）プロファイルで表し、dt ごとに時刻 t、位置 s、速度 v、加速度 a をサンプリングします。

drills-about-umeyama-2d = numpy の default_rng(seed) で n 個のランダムな点 X を作り、Y = 1.3 R(35°) X + (0.4, −0.2) に標準偏差 σ のガウスノイズを加えます。そこから、Umeyama の閉じた形の解（2 × 2 の相互共分散行列の SVD）でスケール、回転角、並進を推定します。CSV には推定値と真の値が並びます。σ = 0 なら、丸め誤差を除いてぴったり一致します。

## キー操作
drills-key-run = ドリルを実行
drills-key-enter = 実行（入力欄で入力中に）
drills-key-download = 結果の最初の CSV をダウンロード
drills-key-switch = 前のドリル / 次のドリル

## Result: warnings and the table switch
drills-table-exact = CSV ファイルどおりの正確な値
drills-table-rounded = 数値は有効数字 6 桁に丸めて表示しています。ダウンロードしたファイルにはすべての桁があります。
drills-warnings-title = この結果を確認してください
