# 平面2リンク IK のページ（#/ik-2r、src/ui/pages/ik2r/）。ページに表示する文字列のすべて。

ik2r-lede = オレンジ色の手先をドラッグすると、逆運動学によって2つの関節がついてきます。リンクをドラッグすると、その関節だけが回ります。このページの数値は、すべてアームの動きに合わせて変わります。

## アームの表示
ik2r-canvas-label = アームの表示：ミリメートル方眼の上の2リンクアーム。手先かリンクをドラッグしてください。矢印キーでも手先を動かせます。
ik2r-elbow-legend = IK の解
ik2r-elbow-down = 肘下げ (q2 ≥ 0)
ik2r-elbow-up = 肘上げ (q2 < 0)
ik2r-ws-show = 作業領域グリッドを表示
ik2r-ws-color = セルの色分け
ik2r-ws-color-reach = 届くかどうか
ik2r-ws-color-manip = 可操作度 |det J|
ik2r-ws-color-err = FK 誤差（対数目盛）
ik2r-reset = リセット
ik2r-clamped = 届きません：手先は、アームが届くいちばん近い点で止まっています。
ik2r-drag-hint = オレンジ色の手先をドラッグすると逆運動学で、肘またはリンク1をドラッグすると q1 だけが、リンク2をドラッグすると q2 だけが動きます。キー操作：矢印で手先を移動、[ ] で q1、- = で q2 を回転、e で肘を反転、r でリセット、w でグリッドを表示。
ik2r-view-notes = 色の付いた輪：手先が届く範囲（作業領域）、{ $inner } mm ≤ r ≤ { $outer } mm。オレンジ色の楕円：関節を単位速度で動かしたときに手先が出せる速度の範囲を { $scale } 倍で描いたもので、軸は特異方向に沿っています（実線が σ_max、破線が σ_min）。
ik2r-ws-summary = 作業領域グリッド { $nx } × { $ny } = { $cells } セル、うち届くセルは { $reachable }（各セルで肘下げ解の IK を計算）。

## 数値の表示
ik2r-readouts-title = リアルタイムの数値
ik2r-ro-q1 = 関節1 q1
ik2r-ro-q2 = 関節2 q2
ik2r-ro-tip = 手先 x, y
ik2r-ro-det = det J
ik2r-ro-w = 可操作度 w
ik2r-ro-sigma = 特異値 σ_min, σ_max
ik2r-ro-jac = ヤコビ行列 J =
ik2r-ro-hint = w = √det(J Jᵀ) は吉川の可操作度です。このアームでは |det J| = L1 L2 |sin q2| に等しくなります。
ik2r-unit-rad = rad
ik2r-unit-deg = °
ik2r-unit-mm = mm
ik2r-unit-m = m
ik2r-unit-m2 = m²
ik2r-unit-m-per-rad = m/rad
ik2r-unit-cells = セル
ik2r-strip-q1 = q1
ik2r-strip-q2 = q2
ik2r-strip-x = x
ik2r-strip-y = y
ik2r-strip-w = w
ik2r-live-summary = アームは q1 { $q1 }°、q2 { $q2 }°；手先は x { $x } mm、y { $y } mm；可操作度 { $w } m²。

## 後から読み込む部分（ヒートマップ、スイーププロット、パラメータ、ダウンロード）
ik2r-more-loading = ヒートマップ、スイーププロット、パラメータ、ダウンロードを読み込んでいます… アームはもう動かせます。
ik2r-more-failed = ヒートマップ、スイーププロット、パラメータ、ダウンロードを読み込めませんでした。ネットワークにつながっていません。アームと数値はそのまま使えます。接続を確かめてから、もう一度お試しください。

## ヒートマップ
ik2r-heatmap-title = 関節空間での可操作度
ik2r-heatmap-label = q1 と q2 を −π から π まで変えたときの |det J| のヒートマップ。現在の姿勢に印があります。矢印キーで印を動かせます。
ik2r-heatmap-hint = 色は (q1, q2) の組ごとの |det J| で、白い丸が現在の姿勢です。セルにポインタを合わせると、その姿勢が灰色の影のアームで表示され、クリックまたはタップするとその姿勢に移ります。赤い破線は特異姿勢 q2 = 0（伸びきった状態）と q2 = ±π（折りたたんだ状態）です。
ik2r-heatmap-axis-q1 = q1 [rad]
ik2r-heatmap-axis-q2 = q2 [rad]
ik2r-heatmap-legend = |det J| [m²]
ik2r-heatmap-singular = 特異姿勢 (q2 = 0)
ik2r-heatmap-hover = プレビュー：q1 = { $q1 } rad、q2 = { $q2 } rad、|det J| = { $det } m²

## グラフ
ik2r-plot-title = ヤコビ行列のスイープ（jacobian-2r レシピ）
ik2r-plot-label = q1 に対する det J と w（上）、σ_min と σ_max（下）のグラフ。現在の q1 に印があります。
ik2r-plot-hint = レシピと同じスイープです。q2 をアームの現在の値に保ったまま、q1 を開始値から終了値まで動かします。平面2リンクアームではこれらの値は q2 だけで決まるので、線は水平になります。q2 を回して（リンク2をドラッグ、またはキー - と =）、線がそろって上下するのを確かめてください。オレンジ色の線は現在の q1 です。
ik2r-plot-x = q1 [rad]
ik2r-plot-top = det J, w [m²]
ik2r-plot-bottom = σ [m]
ik2r-plot-det = det J
ik2r-plot-w = w
ik2r-plot-smin = σ_min
ik2r-plot-smax = σ_max

## パラメータ
ik2r-params-title = パラメータ
ik2r-params-hint = 入力するとすぐに反映されます。正しくない値はその欄の横に理由が表示され、直前の正しい値がそのまま使われます。
ik2r-group-arm = アーム
ik2r-group-ws = 作業領域グリッド（ik-workspace）
ik2r-group-sweep = ヤコビ行列のスイープ（jacobian-2r）
ik2r-group-sweep-note = q2 にはアームの現在の値を使います。
ik2r-group-maps = 可操作度マップ
ik2r-field-L1 = リンク1の長さ L1
ik2r-field-L2 = リンク2の長さ L2
ik2r-field-half_mm = 半幅
ik2r-field-step_mm = 刻み
ik2r-field-q1_start = q1 の開始値
ik2r-field-q1_stop = q1 の終了値
ik2r-field-q1_step = q1 の刻み
ik2r-field-res = ヒートマップの解像度
ik2r-hint-res = ヒートマップの1軸あたりのセル数、64〜1,024。図の細かさだけが変わります。
ik2r-field-n = manip-grid の n

## ダウンロード
ik2r-downloads-title = ダウンロード
ik2r-downloads-hint = どの CSV も、下のコマンドを現在のパラメータで実行したときにレシピが書き出すファイルと1バイトも違いません。
ik2r-dl-ik = ik_workspace.csv をダウンロード
ik2r-dl-jac = jacobian_2r.csv をダウンロード
ik2r-dl-manip = manip_ellipse.csv をダウンロード
ik2r-dl-png = アームの表示を画像で保存（PNG）
ik2r-dl-png-hint = いまのアームの表示を、画面と同じ解像度の画像にします。
ik2r-dl-missing-file = { $recipe } レシピは { $file } というファイルを書き出しませんでした。

## ショートカット（? の一覧）
ik2r-key-nudge = 手先を 1 mm 動かす（Shift を押しながらで 10 mm）
ik2r-key-heatmap = ヒートマップにフォーカスがあるとき：姿勢の印を動かす（← → で q1、↓ ↑ で q2 を 0.01 rad。Shift を押しながらで 0.1 rad）
ik2r-key-q1 = q1 を 0.01 rad 回す（Shift を押しながらで 0.1 rad）
ik2r-key-q2 = q2 を 0.01 rad 回す（Shift を押しながらで 0.1 rad）
ik2r-key-elbow = 肘を反転する（もう一方の IK 解）
ik2r-key-reset = すべてを初期値に戻す
ik2r-key-workspace = 作業領域グリッドの表示・非表示

## 解説
ik2r-explain-title = このページで見えるもの
ik2r-ex-branches-title = 1つの問いに2つの答え
ik2r-ex-branches = 逆運動学とは「手先をここに置くには、各関節を何ラジアンにすればよいか」という問いです。2リンクアームでは、届く点のほとんどに答えが2つあり、根元と手先を結ぶ直線をはさんで鏡に映したような形になります。レシピは q2 = +acos(c2) の解を使います。このページではこれを「肘下げ」、q2 = −acos(c2) を「肘上げ」と呼びます。
ik2r-ex-branches-2 = e キーを押すか切り替えボタンを使うと、手先は同じ位置のまま、q2 の符号だけが変わります。輪の縁では2つの解が1つに重なり、輪の外には解がありません。c2 = (x² + y² − L1² − L2²) / (2 L1 L2) が −1〜1 の範囲から外れるからです。
ik2r-ex-jacobian-title = ヤコビ行列
ik2r-ex-jacobian = ヤコビ行列 J は、関節の速度を手先の速度に変換します：(ẋ, ẏ) = J (q̇1, q̇2)。各列は、一方の関節を止めたまま、もう一方を 1 rad/s で回したときの手先の速度なので、成分の単位は m/rad です。ドラッグしながら、列がどう変わるかを見てみましょう。
ik2r-ex-w-title = 可操作度
ik2r-ex-w = 吉川の可操作度 w = √det(J Jᵀ) は、手先があらゆる方向にどれだけ動きやすいかを表す量です。J が正方行列なら |det J| に等しく、このアームでは |det J| = L1 L2 |sin q2| です。肘が直角のときに最大になり、アームがまっすぐ伸びたときと折りたたまれたときに 0 になります。
ik2r-ex-ellipse = オレンジ色の楕円（可操作度楕円）は、関節を単位速度で動かしたときに手先が出せる速度をすべて表したものです。長い半軸 σ_max の向きには動きやすく、短い半軸 σ_min の向きには動きにくいことを示します。σ_min × σ_max = w です。
ik2r-ex-sing-title = 特異姿勢
ik2r-ex-sing = q2 = 0（伸びきった状態）と q2 = ±π（折り返した状態）では2本のリンクが一直線に並び、det J = 0、σ_min = 0 になります。このとき、関節をどれだけ速く回しても手先はアームの向きには動けません。また、この姿勢の近くで IK を解くと、とても大きな関節速度が必要になります。ヒートマップでは破線、アームの表示では輪の縁がこの姿勢にあたります。
ik2r-ex-flat-title = スイープの線が水平になる理由
ik2r-ex-flat = アーム全体を根元のまわりに回しても形は変わらないので、det J、w、特異値は q2 だけで決まります。jacobian-2r レシピは q2 を固定して q1 を動かすため、どの行も（丸め誤差を除いて）同じ値になります。ヒートマップが横縞になるのも同じ理由です。

## このページのもとになったレシピ（BSV のページの記載どおり）
ik2r-recipes-title = このページのもとになったレシピ
ik2r-recipes-hint = このページは、次の3つの BSV レシピをブラウザの中で計算しています。上のダウンロードは、それぞれの CSV です。
ik2r-rc-input = 入力
ik2r-rc-output = 出力
ik2r-rc-prereq = 必要なもの
ik2r-rc-steps = 手順
ik2r-rc-expected = 期待される結果
ik2r-rc-ik-title = 平面2リンクアームの IK 作業領域をサンプリングする
ik2r-rc-ik-summary = 平面を格子に区切って届くセルに印を付け、肘下げ解の IK と FK 誤差（ミリメートル）を記録します。
ik2r-rc-ik-input = L1, L2 (m)、半幅 mm、刻み mm（初期値 0.12 0.10 200 10）。
ik2r-rc-ik-output = 到達可能フラグと関節角を含む ik_workspace.csv。
ik2r-rc-ik-prereq = Python 3 と numpy。
ik2r-rc-ik-step1 = スクリプトを保存します。
ik2r-rc-ik-step2 = 実行：python planar_ik_workspace.py 0.12 0.10 200 10
ik2r-rc-ik-step3 = グラフにする前に、reachable=1 の行だけを取り出します。
ik2r-rc-ik-expected = 長方形の格子の CSV。輪（円環）の外では reachable=0 になります。
ik2r-rc-ik-note = このページでは：「作業領域グリッドを表示」で、この格子をアームの下に重ねて描きます。
ik2r-rc-jac-title = 平面2R のヤコビ行列と可操作度のスイープ
ik2r-rc-jac-summary = q2 を固定して q1 を動かし、det(J)、吉川の可操作度、特異値を書き出します。シミュレーションを理解するためのものです。
ik2r-rc-jac-input = L1, L2 (m)、q1 の開始・終了・刻み、q2（初期値 0.12 0.10 0 1.57 0.1 0.8）。
ik2r-rc-jac-output = jacobian_2r.csv。
ik2r-rc-jac-prereq = Python 3 と numpy。
ik2r-rc-jac-step1 = スクリプトを保存します。
ik2r-rc-jac-step2 = 実行：python jacobian_planar_2r.py
ik2r-rc-jac-step3 = 特異姿勢の近くで可操作度が下がるのを確かめます。
ik2r-rc-jac-expected = 数十行。特異姿勢に近いところでは、可操作度の最小値が小さくなります。
ik2r-rc-jac-note = このページでは：スイープをグラフにします。CSV の q2 には、初期値の 0.8 ではなくアームの現在の q2 を使います。
ik2r-rc-manip-title = 平面2R の可操作度グリッド
ik2r-rc-manip-summary = 関節空間の格子の上で |det J| をサンプリングします。IK Field Lab と組み合わせて使います。
ik2r-rc-manip-input = L1 L2 n（初期値 0.12 0.10 24）。
ik2r-rc-manip-output = manip_ellipse.csv。
ik2r-rc-manip-prereq = Python 3 の標準ライブラリだけ。
ik2r-rc-manip-step1 = スクリプトを保存します。
ik2r-rc-manip-step2 = 実行：python manip_ellipse_2r.py
ik2r-rc-manip-step3 = 可操作度が最大になる姿勢を探します。
ik2r-rc-manip-expected = n² 行。特異姿勢の近くでは、可操作度がほぼ 0 になります。
ik2r-rc-manip-note = このページでは：ヒートマップが同じ格子を独自の解像度で計算します。CSV には「manip-grid の n」欄の値を使います。ファイル名に ellipse とありますが、中身は |det J| だけで、楕円は含みません。

ik2r-safety = 研究・教育・シミュレーション専用です。ここにあるものは安全規格に適合した制御器ではなく、実機について判断するための根拠にもなりません。
