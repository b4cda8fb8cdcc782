# ドリル一覧のページ（#/drills、src/ui/pages/drills/）。レシピのタイトル・説明・引数のラベル
# （recipes.ftl）とカーネルのエラー（errors.ftl）を除く、ページに表示する文字列のすべて。

drills-title = すべてのドリル
drills-blurb = 12 のドリルのどれでも、好きな値で実行し、Python のレシピと同じ CSV ファイルをダウンロードできます。
drills-lede = ドリルを選び、値を決めて実行しましょう。ダウンロードするファイルは、同じ引数で実行した Python のレシピとファイル名・列・数値まで同じです。結果の下にあるコマンドを使えば、同じ結果を手元で再現できます。データがこのページの外に送られることはありません。

## フォーム
drills-picker-label = ドリル
drills-args-legend = 引数（コマンドラインでの順番）
drills-flags-legend = オプション
drills-flags-note = bsv コマンドだけにある追加の設定です。Python のレシピにはオプションがなく、常にこの既定値を使います。
drills-default = 既定値：
drills-run = 実行
drills-reset = 既定値に戻す
drills-file-open = CSV ファイルを開く…
drills-file-sample = 内蔵のラベル付きサンプルを使う
drills-file-using-sample = 入力：内蔵のラベル付きサンプル（{ $name }、{ $rows } 行）
drills-file-using = 入力：{ $name }（{ $size }）
drills-file-using-rows = 入力：{ $name }（{ $size }、{ $rows } 行、関節の列が { $joints } 個）
drills-file-missing = このリンクではファイル「{ $name }」が使われていました。実行するには、もう一度開いてください。ファイルは手元のコンピューターから外に出ないため、リンクには含められません。
drills-file-too-large = 「{ $name }」は { $size } あり、このドリルで読み込める上限の { $limit } を超えているため、開きませんでした。
drills-file-unreadable = 「{ $name }」を読み込めませんでした（{ $reason }）。
drills-reading = { $name } を読み込んでいます…

## 各欄の下に表示する範囲
drills-hint-number = 任意の数値。
drills-hint-positive = 0 より大きい値。
drills-hint-pendulum-duration = 秒、0 より大きい値。int(時間 ÷ 時間刻み) ステップを計算し、ステップ数は 1〜{ $max } です（既定の時間刻みなら { $seconds } 秒まで）。
drills-hint-pendulum-damping = 0 以上。0 にすると、物体の本当のエネルギーは（積分誤差を除いて）一定に保たれます。
drills-hint-pendulum-angle = 真下にぶら下がった状態からの角度（度）。任意の数値。
drills-hint-pendulum-timestep = 秒、0 より大きい値。小さくするほど行が増えます。ステップ数は最大 { $max } です。
drills-hint-pendulum-integrator = euler はレシピと同じ MuJoCo の既定（半陰的オイラー法、減衰は陰的に扱う）、rk4 は古典的な 4 次のルンゲ・クッタ法です。
drills-hint-link = メートル、{ $min }〜{ $max }。
drills-hint-ik-half = ミリメートル、0〜{ $max }。
drills-hint-ik-step = ミリメートル、0 より大きい値。格子は最大 { $max } × { $max } セルです。
drills-hint-traj-file = t_s 列（秒、常に増加）と関節ごとの列をもつ CSV。note 列は取り除かれます。{ $limit } まで読み込めます。
drills-hint-traj-dt = 秒、0 より大きい値。出力は最大 { $max } セル（行数 × 関節数）です。
drills-hint-dh-angles = 3 つの角度（ラジアン）をカンマで区切って入力します。
drills-hint-angle-range = ラジアン、−{ $max }〜{ $max }。
drills-hint-jacobian-stop = ラジアン、q1 の開始値以上、{ $max } 以下。
drills-hint-jacobian-step = ラジアン、0 より大きい値。サンプル数は最大 { $max } です。
drills-hint-cubic-duration = 秒、{ $min }〜{ $max }。
drills-hint-rows-dt = 秒、0 より大きい値。最大 { $max } 行です。
drills-hint-se3-position = メートル。任意の数値。
drills-hint-se3-angle = 度ではなくラジアン。任意の数値。
drills-hint-seed = 0〜2⁶³ − 1 の整数（numpy の default_rng が受け付ける範囲）。同じシードなら Python と同じ乱数になります。
drills-hint-rrt-iterations = 0〜{ $max } の整数。ゴールに届いた時点で木の成長は止まります。最近傍ノードの探索は木の大きさの 2 乗で重くなるので、大きな値では数秒かかります。
drills-hint-rrt-goal = 0〜1（単位正方形の中）。障害物の内側にあるゴールには、決して届きません。
drills-hint-pid-gain = 任意の数値。
drills-hint-pid-tau = 秒、0〜{ $max }。
drills-hint-pid-steps = 0〜{ $max } の整数（1 ステップ 0.05 秒なので { $seconds } 秒まで）。
drills-hint-manip-n = 1〜{ $max } の整数。n × n 行なので、最大 { $rows } 行です。
drills-hint-trapezoid-distance = 大きさ { $max } までの任意の数値。符号は無視されます。
drills-hint-trapezoid-limit = 0 以外で、大きさは { $min }〜{ $max }。符号は無視されます。
drills-hint-umeyama-sigma = 0 以上（0 ならノイズなしで、ぴったり一致します）。
drills-hint-umeyama-n = { $min }〜{ $max } の整数。

## 「実行」の横に表示する状態
drills-running = 実行中…
drills-large = 計算量の多い実行です。「実行」ボタン（または Enter）を押すと計算します。実行中はページが応答しなくなり、最大のサイズでは数秒かかります。
drills-invalid = 赤で示した値を直してから、もう一度実行してください。
drills-done = { $ms } ミリ秒で完了しました。
drills-failed = ドリルはエラーで止まりました。理由はメッセージを見てください。

## ページを開いたリンクについてのお知らせ
drills-url-unknown-recipe = このリンクのドリル「{ $id }」は存在しないため、代わりに「{ $title }」を表示しています。
drills-url-ignored = このリンクには、このドリルが受け付けない値が含まれていたため、無視しました：{ $keys }
drills-url-invalid = このリンクの値の一部が正しくありません（{ $keys }）。理由は各欄の横のメッセージを見てください。
drills-url-file = このリンクではファイル「{ $name }」が使われていました。実行するには、もう一度開いてください。

## 結果
drills-output-title = 結果
drills-output-empty = まだ何も計算していません。「実行」を押すか、どれかの欄で Enter を押してください。
drills-stale = この結果を計算したあとで値が変わりました。「実行」（または Enter）で更新してください。下のファイルとコマンドは、互いに対応したままです。
drills-summary-label = レシピが表示する行
drills-file-size = { $rows_text } 行、{ $columns } 列、{ $size }
drills-download = { $file } をダウンロード
drills-preview-label = { $file } のプレビュー
drills-preview-empty = ヘッダーだけです。この実行ではデータ行が書き出されませんでした。
drills-preview-all = ファイル全体（{ $rows_text } 行）を表示しています。
drills-preview-some = { $rows_text } 行のうち、最初の { $shown } 行を表示しています。ダウンロードしたファイルには全行が入っています。
drills-preview-columns = { $columns } 列のうち { $shown } 列を表示しています。
drills-download-failed = { $file } を保存できませんでした：{ $error }
drills-commands-title = 同じ実行をコマンドラインで
drills-commands-hint = どちらの行をターミナルで実行しても、同じファイルが得られます（Python のレシピには Python 3 と必要なライブラリが、bsv にはこのプロジェクトのコマンドラインツールが必要です）。
drills-cmd-python = Python のレシピ
drills-cmd-bsv = BSV のコマンドライン
drills-copy = コピー
drills-copied = コマンドをクリップボードにコピーしました。
drills-copy-failed = このブラウザではコピーが許可されていません。コマンドを選択して Ctrl+C（Mac では ⌘C）を押してください。
drills-python-no-options = Python のレシピにはオプションがないため、この行には { $options } が含まれず、既定値での結果になります。この実行を再現できるのは bsv の行だけです。
drills-file-note = これらのコマンドは、{ $name } があるフォルダーで実行してください。

## 解説
drills-about-title = 何を計算するのか
drills-quirks-title = Python のレシピの癖（あえてそのまま再現しています）
drills-about-parity = 数値は、bsv コマンドと同じ Rust のコードがブラウザの中で計算し、Python と同じ書き方（往復で値が変わらない最短の桁数）で書き出します。そのため、Python のレシピが出力した CSV と diff を取っても差は出ません。

drills-about-pendulum-energy = 減衰のある振り子（ヒンジに付いたカプセル）を、MuJoCo とまったく同じ方法で int(時間 ÷ 時間刻み) 回ステップさせます。各行には角度 θ、角速度 ω と 3 つのエネルギー、ke = ½ m (L ω)²、pe = m g (z + L)、total = ke + pe が入ります。減衰があれば total は減っていくはずです。表示されるドリフトは max(total) − min(total) です。
drills-quirk-pendulum-energy = エネルギーは、シミュレーションしているカプセルではなく、距離 L の先端にある質量 m の質点として計算しています。そのため total はこの物体の本当の力学的エネルギーではなく、減衰がなくても変化します。pe には各ステップの前の先端の高さ（MuJoCo が最後に位置を計算した時点）を使い、時刻の列は i·h ですが、状態は i 番目のステップの後のものです。

drills-about-ik-workspace = 根元のまわり ±half_mm の範囲を、step_mm 間隔の正方格子で覆います。各セル (x, y) について、c2 = (x² + y² − L1² − L2²) / (2 L1 L2) が −1〜1 に入れば 2 リンクアームの手先が届きます。届くセルには肘下げの解 q2 = acos c2、q1 = atan2(y, x) − atan2(L2 sin q2, L1 + L2 cos q2) と、その解の順運動学とセルとの距離 fk_err_mm（丸め誤差だけ）を記録します。届かないセルでは角度の欄は空になります。

drills-about-traj-resample = 時刻の列 t_s と関節ごとの列をもつ軌道を読み込み、各関節を等間隔の時刻 t0, t0 + dt, … 最後の時刻まで線形補間します（numpy の interp）。ファイルを指定しない場合、レシピはまずラベル付きの合成サンプルを書き出し、それをリサンプリングするので、ファイルが 2 つできます。
drills-quirk-traj-resample = サンプル（またはあなたのファイル）の note 列は、出力から取り除かれます。時刻は行ごとに必ず増えていく必要があります。Python のレシピはこれを確かめず、np.interp は警告なしにおかしな値を返します。このページではそのようなファイルを受け付けず、時刻が増えていない最初の行を示します。

drills-about-dh-fk = 3 関節の固定されたデモ用チェーンの順運動学です。リンクごとに修正 DH 変換（関節角 θ = q ＋ リンクのオフセット）を直前のフレームに掛けていき、ベースフレームから順に、各フレームの原点 x, y, z と roll, pitch, yaw（XYZ 固定角）を書き出します。
drills-quirk-dh-fk = このチェーンは、古典的な（標準）DH ではなく修正 DH（Craig の流儀）のパラメータを使います。同じ 4 つの数値を古典 DH のツールに入れると、別のフレームになります。ベースの行は文字どおりの 0 で書き出され、参照実装が負のゼロを計算するところ（atan2(−0.0, 1) のピッチ）には −0.0 が現れます。値は 0 と同じで、Python の表示に合わせているだけです。

drills-about-jacobian-2r = q2 を固定したまま、q1 を開始値から終了値（この値を含む）まで刻みごとに動かします。各行には手先の位置、det J = L1 L2 sin q2、吉川の可操作度 w = √det(J Jᵀ)、ヤコビ行列の特異値 σ_min, σ_max が入ります。平面 2R アームではこれらは q2 だけで決まるので、（丸め誤差を除いて）どの行も同じ値になります。アーム全体を回しても、動きやすさは変わらないということです。

drills-about-cubic-path = 3 次式 q(t) = q0 + a2 t² + a3 t³（a2 = 3 (q1 − q0) / T²、a3 = −2 (q1 − q0) / T³）は、静止した状態から始まり静止した状態で終わるように、時間 T で q0 から q1 まで動きます。0 から T まで dt ごとに、速度 qd と加速度 qdd とともにサンプリングします。加速度は両端で 0 にならず、動き始めと止まるときに跳びます。より滑らかな計画器が 5 次多項式を使うのはこのためです。

drills-about-se3-relative = 2 つの姿勢（x, y, z と roll, pitch, yaw、R = Rz(yaw) Ry(pitch) Rx(roll)）から同次変換 T_A と T_B を作り、T_A⁻¹ T_B を書き出します。フレーム A から見て、フレーム B がどこにあり、どう回っているかを表します。
drills-quirk-se3-relative = Python のレシピの説明には角度は「度」とありますが、コードでは値をそのまま cos と sin に渡しているので、実際にはラジアンです（0.2 rad ≈ 11.5°）。30° のつもりで 30 と入力すると、30 rad 回ることになります。角度は回転行列から読み戻すので、pitch は −π/2〜π/2 の範囲になり、pitch が ±π/2（ジンバルロック）のときは roll を 0 にします。

drills-about-rrt-2d = 単位正方形の中で、(0.1, 0.1) からゴールに向かって、箱形の障害物 [0.35, 0.65] × [0.25, 0.75] をよけながら RRT（高速探索ランダム木）を伸ばします。毎回 numpy の default_rng(seed) で点を 1 つ引き（10 回に 1 回はゴールそのもの）、いちばん近いノードからその点に向かって 0.05 進み、正方形の中にとどまって箱に触れなければその一歩を採用します。ゴールから 0.06 以内のノードができたら終わりです。rrt_path.csv はスタートからゴールまでの経路、rrt_nodes.csv は親の番号つきの木全体です。
drills-quirk-rrt-2d = 線分の衝突判定は、等間隔の 12 点でしか行いません。そのため、線分が箱の角をかすめて通り抜けることがあります。max_iter 回の反復でゴールに届かなかった場合（ゴールを箱の中に置いてみてください）、rrt_path.csv はヘッダーだけになり、経路長は nan と表示されます。

drills-about-pid-step = 1 次遅れのプラント y ← y + a (u − y)（a = dt / (τ + dt)、dt = 0.05 秒）のまわりに離散 PID 制御器でループを閉じ、目標値 r = 1 のステップ入力を与えます。各ステップで誤差 e = r − y、その積算と変化、指令 u = Kp e + Ki ∫e + Kd de/dt、新しい出力 y を計算します。表示される final_y を見れば、ループがどこまで目標に近づいたかがわかります。Ki を大きくすると残りの誤差が消え、Kp を大きくするとオーバーシュートが出ます。ループが不安定になるゲインでは値が増え続け、Python と同じように最後は inf、そして nan と表示されます。

drills-about-manip-grid = q1 と q2 をそれぞれ −π〜π の範囲で n × n の格子に区切り、平面 2R アームの det J = L1 L2 sin q2 を計算して、|det J| の最大値とその位置を表示します。アームは肘が直角のときにいちばん動きやすく、伸びきったときや折り返したときに特異（det J = 0）になります。
drills-quirk-manip-grid = Python のファイル名は manip_ellipse_2r.py で、出力も manip_ellipse.csv ですが、楕円は計算していません。detJ は det J、manip は |det J|（可操作度楕円の面積の倍率）です。楕円そのものは、平面 2 リンク IK プレイグラウンドで描いています。

drills-about-trapezoid-profile = |distance| の移動を、amax で加速し、vmax で等速移動し、amax で減速する（vmax に届かなければ三角形になる）プロファイルで表し、dt ごとに時刻 t、位置 s、速度 v、加速度 a をサンプリングします。
drills-quirk-trapezoid-profile = 時刻は t ≤ t_total のあいだ t += dt の足し算を繰り返して進むので、丸め誤差が積み重なり、それが行数を決めます。各行の時刻は round(t, 5) で表示されます。三角形の場合、減速部分では届かなかった vmax から求めた d_acc をそのまま使うため、位置が行き過ぎます。0.2 1.0 2.0 では、表は s = 0.2 ではなく s ≈ 0.35 で終わります。

drills-about-umeyama-2d = numpy の default_rng(seed) で n 個のランダムな点 X を作り、Y = 1.3 R(35°) X + (0.4, −0.2) に標準偏差 σ のガウスノイズを加えます。そこから、Umeyama の閉じた形の解（2 × 2 の相互共分散行列の SVD）でスケール、回転角、並進を推定します。CSV には推定値と真の値が並びます。σ = 0 なら、丸め誤差を除いてぴったり一致します。
drills-quirk-umeyama-2d = SVD の結果が鏡映（det R < 0）になったとき、レシピは Umeyama の方法どおり U の列の符号を反転しますが、スケールは (S1 + S2) / var_x のままにします。Umeyama の方法では S1 − S2 を使います。影響が出るのは、点の配置がほぼ退化しているか、ノイズがとても大きい場合だけです。

## キー操作
drills-key-run = ドリルを実行
drills-key-enter = 実行（入力欄で入力中に）
drills-key-download = 結果の最初の CSV をダウンロード
drills-key-switch = 前のドリル / 次のドリル
