# 演習（src/view/exercises）：ex-<id>-prompt、-hint、-explain。選択式は ex-<id>-choice-<n> と
# ex-<id>-why-<n>（n は 1 から）も持つ。予想の解説には $truth（カーネルの値と単位）が渡される。
# そのあとにページの演習セクション（src/ui/exercises）の文言。セクションのコードと一緒に読み込まれ、
# どのページの最初の読み込みにも入らない。進み具合のファイルとクラスのページの文言は progress.ftl。

## #/ik-2r
ex-ik-singular-prompt = 目標：可操作度 w が 0.001 m² 未満になる姿勢に腕を置いてください。ただし先端は作業領域の内側（縁の上ではなく）に置きます。
ex-ik-singular-hint = w = l1·l2·|sin q2| は肘の角度だけで決まります。sin q2 が小さくなるのはどんな肘の角度でしょう。届く範囲の縁の少し手前で止めます。
ex-ik-singular-explain = q2 = 0（伸び切り）や q2 = π（折り返し）の近くでは、2 つの関節がほぼ同じ向きに先端を動かすので、ヤコビアンが方向を 1 つ失いかけ、w が 0 に近づきます。そうした姿勢は作業領域の外側の円と内側の円のすぐ内側にあります。
ex-ik-w-pose-prompt = 画面の姿勢の可操作度 w を m² で予想してください。
ex-ik-w-pose-hint = この腕では w = |det J| = l1·l2·|sin q2| です。q2 は姿勢から読み取れます。
ex-ik-w-pose-explain = w = l1·l2·|sin q2| = { $truth }。q1 には依存しません。腕全体を回しても、先端の動かしやすさは変わりません。
ex-ik-best-elbow-prompt = この腕の可操作度が最大になる肘の角度 q2 は何度でしょう（0〜180 度）。
ex-ik-best-elbow-hint = w = l1·l2·|sin q2| です。|sin q2| が最大になるのはどこでしょう。
ex-ik-best-elbow-explain = w は q2 = { $truth } で最大です。リンクが直角だと、2 つの関節が先端を互いに直交する向きに動かします。
ex-ik-singular-where-prompt = 平面 2 リンクアームが特異になるのは、作業領域のどこでしょう。
ex-ik-singular-where-hint = 特異とは det J = 0 のことで、det J = l1·l2·sin q2 です。
ex-ik-singular-where-explain = det J = l1·l2·sin q2 が 0 になるのは q2 = 0 と q2 = π だけです。腕が伸び切るか折り返し、先端が作業領域の外側か内側の円の上にある姿勢です。先端をどちらかの縁まで動かすと w が 0 に落ちるのが見えます。
ex-ik-singular-where-choice-1 = 先端が根元にあるときだけ
ex-ik-singular-where-why-1 = w は肘の角度 q2 だけで決まり、先端の向きには依存しません。しかも先端が根元に届くのは l1 = l2 のときだけです。
ex-ik-singular-where-choice-2 = 作業領域の外側の円と内側の円の上（腕が伸び切ったときと折り返したとき）
ex-ik-singular-where-why-2 = 正解：sin q2 = 0 となるのは q2 = 0 と q2 = π で、ちょうど先端が根元から l1 + l2 または |l1 − l2| の距離にある姿勢です。
ex-ik-singular-where-choice-3 = 先端が x 軸の上にあるときはいつでも
ex-ik-singular-where-why-3 = q1 は腕全体を回すだけで、w は q1 に依存しません。
ex-ik-singular-where-choice-4 = どこにもない：2 リンクアームに特異点はない
ex-ik-singular-where-why-4 = q2 = 0 では 2 本のリンクが平行になり、どちらの関節も先端を同じ向きに動かすので、J の階数が落ちます。

## #/dh-fk
ex-dh-tip-height-prompt = 最後の座標系（座標系 3）の原点の高さ z をメートルで予想してください。
ex-dh-tip-height-hint = 関節 1 は高さ 0.10 m にあり、関節 2 が長さ 0.25 m のリンクを上下に傾けます。高さを変えるのは q2 だけです。
ex-dh-tip-height-explain = z = 0.10 − 0.25·sin q2 = { $truth }。関節 1 は鉛直軸まわりに回り、関節 3 は最後の座標系をその場で回すだけなので、どちらも高さを変えません。
ex-dh-raise-prompt = 目標：最後の座標系の原点を高さ 0.3 m 以上に上げてください。
ex-dh-raise-hint = 高さは 0.10 − 0.25·sin q2 です。リンクを持ち上げるのは q2 がどちらの符号のときでしょう。
ex-dh-raise-explain = q2 を負にするとリンクが上を向きます。sin q2 ≤ −0.8 で高さは 0.3 m に達し、リンクが真上を向いたとき最大の 0.35 m になります。
ex-dh-q3-origin-prompt = q1 と q2 はそのままで q3 を変えます。最後の座標系の原点はどうなるでしょう。
ex-dh-q3-origin-hint = 修正 DH 法では、リンク i の長さ a(i−1) は関節 i より手前にあります。
ex-dh-q3-origin-explain = 修正 DH 法ではリンク長 a2 = 0.25 m が関節 3 の手前にあるので、関節 3 は座標系 3 の原点にあります。q3 はそこで座標軸を回すだけで、何も動かしません。
ex-dh-q3-origin-choice-1 = 動かない：q3 は座標系を自分の z 軸まわりに回すだけ
ex-dh-q3-origin-why-1 = 正解：0.25 m の長さは関節 3 の手前に置かれた a2 なので、関節 3 は座標系 3 の原点にあり、それを回すだけです。
ex-dh-q3-origin-choice-2 = 半径 0.25 m の円の上を動く
ex-dh-q3-origin-why-2 = そうなるには関節 3 の先にリンクが要ります。このチェーンでは 0.25 m のリンクは関節 3 の手前にあります。
ex-dh-q3-origin-choice-3 = 上下に動く
ex-dh-q3-origin-why-3 = リンクを傾けて高さを変えるのは q2 だけです。
ex-dh-q3-origin-choice-4 = 鉛直軸のまわりを回る
ex-dh-q3-origin-why-4 = それは q1 の働きです。

## #/se3-relative
ex-se3-distance-prompt = 座標系 A と B の原点の間の距離をメートルで予想してください。
ex-se3-distance-hint = 相対姿勢の x、y、z は A の座標系で見た B の原点です。距離はどの座標系で測っても変わりません。
ex-se3-distance-explain = 相対位置の √(x² + y² + z²) = { $truth }。A を回すと 3 つの数は変わりますが、この長さは変わりません。
ex-se3-ahead-prompt = 目標：A を回した状態で、B を A 自身の x 軸に沿って 0.1 m 前方に、A と同じ向きで置いてください（相対姿勢が 0.1, 0, 0, 0, 0, 0 から 1 mm と 0.01 rad 以内）。
ex-se3-ahead-hint = ワールドで見た A の x 軸は A の回転行列の第 1 列です。ヨー ψ だけなら (cos ψ, sin ψ, 0) です。B にも A と同じロール・ピッチ・ヨーが要ります。
ex-se3-ahead-explain = T_A⁻¹ T_B は A の座標系で見た B です。B の原点は A の原点から A の x 軸に沿って 0.1 m 進んだ点、B の回転は A と同じでなければ相対回転が 0 になりません。
ex-se3-swap-prompt = A と B を入れ替えます。相対姿勢はどうなるでしょう。
ex-se3-swap-hint = T_A⁻¹ T_B と T_B⁻¹ T_A を書き出して、掛け合わせてみましょう。
ex-se3-swap-explain = T_B⁻¹ T_A は T_A⁻¹ T_B の逆変換で、B から見た A です。その位置は単なる −p ではなく、−p を相対回転の逆で回した −Rᵀp です。
ex-se3-swap-choice-1 = 変わらない
ex-se3-swap-why-1 = T_B⁻¹ T_A は B から見た A であって、A から見た B ではありません。
ex-se3-swap-choice-2 = 逆変換になる
ex-se3-swap-why-2 = 正解：(T_A⁻¹ T_B)⁻¹ = T_B⁻¹ T_A です。
ex-se3-swap-choice-3 = 6 つの数がすべて符号反転する
ex-se3-swap-why-3 = [R p] の逆は [Rᵀ −Rᵀp] で、位置も回転されます。ロール・ピッチ・ヨーの符号を反転しても Z·Y·X 回転は元に戻りません。
ex-se3-swap-choice-4 = 単位行列になる
ex-se3-swap-why-4 = A と B が同じ姿勢のときだけです。

## #/umeyama-2d
ex-umeyama-angle-prompt = 当てはめが推定する回転角を度で予想してください。
ex-umeyama-angle-hint = 目標点は、点を真の角度だけ回し、拡大して平行移動し、少しの雑音を加えたものです。
ex-umeyama-angle-explain = 当てはめの推定は { $truth } です。真の 35° に近く、ずれは雑音の分だけです。
ex-umeyama-exact-prompt = 目標：当てはめを厳密にしてください（RMSE が 1e-9 未満）。
ex-umeyama-exact-hint = 目標点が点の完全な相似変換と違ってしまう原因は何でしょう。
ex-umeyama-exact-explain = 雑音がなく（σ = 0）鏡映もなければ、目標点は点を拡大・回転・平行移動した正確な写しなので、当てはめは丸め誤差の範囲でそれを復元します。
ex-umeyama-mirror-prompt = 目標点を鏡映します（相似変換の前に y → −y）。当てはめは何を返すでしょう。
ex-umeyama-mirror-hint = Umeyama の方法は R を回転（det R = +1）として s·R を探します。
ex-umeyama-mirror-explain = 鏡映された目標点には det R = −1 が必要ですが、そんな回転はありません。この方法は R を回転のまま保ち（det C < 0 なら最後の特異方向を反転）、回転で表せる最良の当てはめを、大きな RMSE とともに返します。
ex-umeyama-mirror-choice-1 = 鏡映も含めて返す
ex-umeyama-mirror-why-1 = この方法は鏡映をわざと取り除くので、R は回転のままです。
ex-umeyama-mirror-choice-2 = 見つけられる最良の回転を、大きな RMSE とともに返す
ex-umeyama-mirror-why-2 = 正解：鏡映は回転ではないので、当てはめは最も近い（鏡映なしの）相似変換を返し、説明できない分が RMSE に表れます。
ex-umeyama-mirror-choice-3 = エラー：当てはめは存在しない
ex-umeyama-mirror-why-3 = 当てはめは必ず存在します。ただ、良くないだけです。
ex-umeyama-mirror-choice-4 = 負の倍率を返す
ex-umeyama-mirror-why-4 = 倍率は正のままです。鏡映は倍率ではなく、R の最後の特異方向で処理されます。

## #/pendulum-energy
ex-pendulum-euler-dt-prompt = ページの時間刻み h でオイラー法を使うとき、実行全体でのエネルギーの相対的なずれ（終了時のエネルギー誤差、E(0) に対する %）を予想してください。
ex-pendulum-euler-dt-hint = 半陰的オイラー法はエネルギーを厳密には保ちません。誤差はおよそ h² に比例して小さくなります。大きな h で一度走らせてから、比で見積もってみましょう。
ex-pendulum-euler-dt-explain = 実行の終わりで (E + W − E(0)) / E(0) = { $truth }。カプセルの真のエネルギーにダンパーの仕事を足したものを、初期値と比べた値です。時間刻みを 10 倍にすると誤差はおよそ 100 倍になります。
ex-pendulum-period-prompt = ページが実行全体から測る振り子の周期を秒で予想してください。
ex-pendulum-period-hint = 微小振幅の公式 2π·√(I / (m g L/2)) が使えるのは小さな振れだけです。この振り子は 120° から始まります。
ex-pendulum-period-explain = ページはゼロ交差の間隔から { $truth } と測ります。大きな振れは微小振幅の周期より遅くなります。折り返し点の近くでは円弧に沿った重力の成分が公式の想定より弱く、そこで長く過ごすからです。
ex-pendulum-integrator-prompt = ページの時間刻み h で、実行の終わりのエネルギー誤差が小さいのはどちらの積分法でしょう。
ex-pendulum-integrator-hint = 比較をオンにして誤差のグラフを見ましょう。縦軸は対数目盛です。
ex-pendulum-integrator-explain = 同じ時間刻みで、RK4 のエネルギー誤差はオイラー法より何桁も小さいままです。比較をオンにした誤差のグラフに両方が表示されます。
ex-pendulum-integrator-choice-1 = オイラー法
ex-pendulum-integrator-why-1 = 半陰的オイラー法は 1 次の方法で、エネルギーの揺れは h とともに大きくなります。
ex-pendulum-integrator-choice-2 = RK4
ex-pendulum-integrator-why-2 = 正解：RK4 は 4 次の方法で、1 ステップあたり 4 回の評価と引き換えに誤差がはるかに小さくなります。
ex-pendulum-integrator-choice-3 = どちらもほぼ同じ
ex-pendulum-integrator-why-3 = 2 つの誤差は何桁も違います。誤差のグラフで確かめられます。
ex-pendulum-over-top-prompt = 目標：頂点より下から始めて、シミュレーションの振り子を頂点の向こうまで回してください。本物の振り子では起こりません。
ex-pendulum-over-top-hint = 減衰はエネルギーを奪います。減衰がないとき、大きな時間刻みはオイラー法のエネルギーをどうするでしょう。
ex-pendulum-over-top-explain = 時間刻みが大きいと積分法そのものがエネルギーを足していき、振り子が頂点を越えます。物理ではなく数値解法の誤差です。

## #/pid-step
ex-pid-tune-prompt = 目標：ページのプラント（τ = 0.8 s）で、レシピの 80 ステップ以上の実行について、オーバーシュートが 5 % 未満、2 % 整定時間が 1.5 s 未満になるように Kp、Ki、Kd を調整してください。
ex-pid-tune-hint = レシピのゲインでは遅すぎて整定しません。Ki を増やすと残りの誤差が早く消えますが、増やしすぎるとオーバーシュートします。
ex-pid-tune-explain = Kp を大きくすると立ち上がりが速くなり、Ki が最後の誤差を 0 にし、少しの Kd がオーバーシュートを抑えます。Kp 2、Ki 3、Kd 0.05 ではオーバーシュート 1.5 %、整定は 1.1 s です。
ex-pid-final-y-prompt = 実行の終わりのプラント出力 y を予想してください。
ex-pid-final-y-hint = このループは実行中に目標値に届くでしょうか。積分項が育つ速さを見てみましょう。
ex-pid-final-y-explain = y は { $truth } で終わります。レシピの小さな Ki では、実行が終わる時点でも積分項がまだ誤差を減らしている途中です。
ex-pid-p-only-prompt = Ki = 0 にして Kp = 1.2 のままにします。長く走らせると y はどこに落ち着くでしょう。
ex-pid-p-only-hint = 静止すると y = u、そして e = r − y として u = Kp·e です。
ex-pid-p-only-explain = P だけのループは y = Kp·(1 − y) となるところで静止します。Kp = 1.2 なら y = Kp / (1 + Kp) = 0.545 です。最後の誤差を消すのは積分項だけです。
ex-pid-p-only-choice-1 = 目標値 r = 1
ex-pid-p-only-why-1 = P 制御は誤差がないと出力を出せません。積分項がなければ最後の誤差を消すものがありません。
ex-pid-p-only-choice-2 = r より下の Kp / (1 + Kp) = 0.545
ex-pid-p-only-why-2 = 正解：静止すると y = Kp·(1 − y) なので、y = Kp / (1 + Kp) です。
ex-pid-p-only-choice-3 = 振動し続ける
ex-pid-p-only-why-3 = 比例制御のもとの 1 次遅れプラントはここで静止します。揺れ続ける理由がありません。
ex-pid-p-only-choice-4 = r より上
ex-pid-p-only-why-4 = y = Kp·(1 − y) から、正の Kp なら y は必ず 1 より小さくなります。
ex-pid-overshoot-prompt = ページのゲインでの応答のオーバーシュートを % で予想してください。
ex-pid-overshoot-hint = オーバーシュートは y の最大値が r = 1 をどれだけ超えるかを、r に対する % で表したものです。
ex-pid-overshoot-explain = y の最大値は r を { $truth } 超えます。Ki を増やすか Kd を減らすと大きくなります。

## #/cubic-path
ex-cubic-peak-velocity-prompt = 3 次補間の関節速度の最大値を rad/s で予想してください。
ex-cubic-peak-velocity-hint = 3 次補間は静止から始まり静止で終わります。速度は放物線で、中間で最大になります。
ex-cubic-peak-velocity-explain = 最大値は t = T/2 で { $truth }、平均速度 (q1 − q0) / T の 1.5 倍です。
ex-cubic-speed-limit-prompt = 目標：0 から 1.2 rad への動きはそのままに、速度の最大値を 1 rad/s 以下にしてください。
ex-cubic-speed-limit-hint = 最大値は 1.5·(q1 − q0) / T です。1 rad/s になる T はいくつでしょう。
ex-cubic-speed-limit-explain = T ≥ 1.8 s なら最大値 1.5 × 1.2 / T は 1 rad/s 以下です。同じ経路を、ゆっくり動きます。
ex-cubic-peak-accel-prompt = 3 次補間の加速度の大きさが最大になるのはどこでしょう。
ex-cubic-peak-accel-hint = q̈ = 2a2 + 6a3·t は t の 1 次式（直線）です。
ex-cubic-peak-accel-explain = q̈ = 6Δ/T²·(1 − 2t/T) は始まりと終わりで最大（レシピの動きでは 6Δ/T² = 7.2 rad/s²）、中間で 0 です。
ex-cubic-peak-accel-choice-1 = 中間の T/2
ex-cubic-peak-accel-why-1 = そこでは速度が最大で、加速度は 0 です。
ex-cubic-peak-accel-choice-2 = 始まりと終わり
ex-cubic-peak-accel-why-2 = 正解：q̈ = 6Δ/T²·(1 − 2t/T) は t = 0 と t = T で最大（符号は逆）で、両端で 0 から跳び上がります。
ex-cubic-peak-accel-choice-3 = ずっと同じ
ex-cubic-peak-accel-why-3 = それは台形プロファイルの加速区間です。3 次補間の加速度は直線的に変わります。
ex-cubic-peak-accel-choice-4 = 全体の 4 分の 1 の時刻
ex-cubic-peak-accel-why-4 = q̈ は始まりの値から直線的に減り、T/4 ではその半分しかありません。

## #/trapezoid-profile
ex-trap-triangle-prompt = 目標：動きを変えて、プロファイルに等速区間がない（三角形）ようにしてください。
ex-trap-triangle-hint = vmax まで加速するには vmax² / (2·amax) の距離が要り、止まるにも同じだけ要ります。
ex-trap-triangle-explain = vmax² / amax ≥ D のとき、動きは vmax に届く前に終わります。距離の半分で加速し、残りで減速します。
ex-trap-accel-end-prompt = プロファイルが加速をやめる時刻を秒で予想してください。
ex-trap-accel-end-hint = 静止から amax で加速して vmax になるまでどれだけかかるでしょう。そこまで行けるだけの距離はあるでしょうか。
ex-trap-accel-end-explain = 加速区間は t = { $truth } で終わります。vmax / amax、三角形なら √(D / amax) です。
ex-trap-total-time-prompt = 動き全体にかかる時間を秒で予想してください。
ex-trap-total-time-hint = 加速と減速の 2 区間を合わせた距離は、vmax で vmax / amax の時間だけ進む距離と同じです。
ex-trap-total-time-explain = 動きは { $truth } かかります。台形なら D / vmax + vmax / amax です。
ex-trap-short-peak-prompt = 距離 0.2 m、vmax 0.5 m/s、amax 1 m/s² のとき、プロファイルが達する最高速度はいくつでしょう。
ex-trap-short-peak-hint = 0.5 m/s まで加速してまた止まるには vmax² / amax の距離が要ります。
ex-trap-short-peak-explain = vmax² / amax = 0.25 m は動きの 0.2 m より長いので、プロファイルは三角形になり、最高速度は vmax より低い √(D·amax) = 0.447 m/s です。
ex-trap-short-peak-choice-1 = 0.5 m/s（vmax）
ex-trap-short-peak-why-1 = 0.5 m/s まで加速して止まるには 0.25 m 要り、この動きの 0.2 m より長くなります。
ex-trap-short-peak-choice-2 = 0.447 m/s（√(D·amax)）
ex-trap-short-peak-why-2 = 正解：三角形は距離の半分で加速するので、v² = 2·amax·D/2 = amax·D です。
ex-trap-short-peak-choice-3 = 0.25 m/s
ex-trap-short-peak-why-3 = vmax の半分になる理由はありません。最高速度は距離と amax で決まります。
ex-trap-short-peak-choice-4 = 0.2 m/s
ex-trap-short-peak-why-4 = それは距離であって、速度ではありません。

## #/traj-resample
ex-traj-rows-prompt = ページの dt で、再サンプリングした表が何行になるか（見出しを除く）予想してください。
ex-traj-rows-hint = 新しい格子は最初のサンプルの時刻から dt ずつ進み、最後のサンプルの時刻を超えない間続きます。
ex-traj-rows-explain = 表は { $truth } 行です。最初のサンプルから最後のサンプルまで、格子の時刻ごとに 1 行で、ちょうど最後の時刻に届けばそれも含みます。
ex-traj-miss-peak-prompt = 目標：再サンプリングした q1 が、軌道の q1 の最大値に 0.05 rad 以上届かなくなる dt を選んでください。
ex-traj-miss-peak-hint = 最大値はあるサンプル時刻にあります。その時刻をまたいでしまう格子はどれでしょう。
ex-traj-miss-peak-explain = 線形補間がサンプルの値を再現するのは、格子の時刻がちょうどそこに来たときだけです。粗い格子が最大値をまたぐと角が削られ、再サンプリングした曲線はそこまで高くなりません。
ex-traj-between-prompt = 再サンプリングした値が、元のサンプルの最大値を超える（または最小値を下回る）ことはあるでしょうか。
ex-traj-between-hint = 新しい値はそれぞれ、その時刻をはさむ 2 つのサンプルから計算されます。
ex-traj-between-explain = 線形補間は新しい値をすべて、はさむ 2 つのサンプルを結ぶ直線の上に置くので、その範囲から出ません。3 次スプラインなら出ることがあります。
ex-traj-between-choice-1 = ある：補間はサンプルの間で行き過ぎる
ex-traj-between-why-1 = それはスプラインで起こることです。2 つのサンプルを結ぶ直線はその間にとどまります。
ex-traj-between-choice-2 = ない：新しい値はどれも、はさむ 2 つのサンプルの間にある
ex-traj-between-why-2 = 正解：np.interp は隣り合うサンプルを直線で結びます。
ex-traj-between-choice-3 = dt がサンプルの間隔より小さいときだけある
ex-traj-between-why-3 = 刻みは関係ありません。どの格子の時刻も、どれかの直線区間の上に来ます。

## #/rrt-2d
ex-rrt-300-prompt = 目標：箱を動かしたり大きさを変えたりして、シード 7 の木がゴールに届くものの、300 回より多くの反復が必要になるようにしてください。
ex-rrt-300-hint = レシピの世界では 120 回で届きます。道をふさがずに、回り道を長くしてみましょう。
ex-rrt-300-explain = 回り道が狭かったり長かったりすると、木をゴールの方へ伸ばすランダムなサンプルが減り、反復が多くかかります。ゴールには届くままでなければなりません。
ex-rrt-path-length-prompt = この実行で見つかる経路の長さを、正方形の一辺を 1 とする単位で予想してください。
ex-rrt-path-length-hint = スタートからゴールへの直線は箱を横切ります。木の経路は 0.05 の歩幅でジグザグに進みます。
ex-rrt-path-length-explain = 経路の長さは { $truth } です。箱を回り込み、しかも RRT の経路は最短からほど遠いものです。
ex-rrt-corner-prompt = 木の辺が箱の角を横切っているのに、プランナーはその辺を受け入れました。なぜでしょう。
ex-rrt-corner-hint = 辺がどう確かめられるかを見ましょう。サブステップに確認点が表示されます。
ex-rrt-corner-explain = 各辺は等間隔の 12 点でしか確かめられません。その間隔より細い角は 2 点の間に入り込み、削られることがあります。
ex-rrt-corner-choice-1 = 各辺で確かめるのは 12 点だけで、その間に収まる細い角は見逃される
ex-rrt-corner-why-1 = 正解：レシピは等間隔の 12 点だけを確かめるので、2 点の間に収まる角は削られます。
ex-rrt-corner-choice-2 = 箱の辺や角は内側に数えない
ex-rrt-corner-why-2 = 箱は閉集合で、辺の上の点も衝突になります。
ex-rrt-corner-choice-3 = ゴールバイアスがあると、ゴールへ向かう辺は箱を通り抜けられる
ex-rrt-corner-why-3 = ゴールバイアスはどこをサンプルするかを選ぶだけで、どの辺も同じように確かめられます。
ex-rrt-corner-choice-4 = 歩幅が箱より長い
ex-rrt-corner-why-4 = 歩幅 0.05 は箱よりずっと短いです。効いているのは確認点の間隔です。
ex-rrt-wall-prompt = 目標：木が実行中にゴールへ届けないように箱を置いてください（反復は 800 回以上、ゴール自体はどの箱の外）。
ex-rrt-wall-hint = 箱は正方形の縁に接してもかまいません。木は何を越えられなければよいでしょう。
ex-rrt-wall-explain = 閉じた壁があれば通れる経路はありません。完全なプランナーならそう答えますが、RRT は予算を使い切るだけです。反復が尽きても、経路がないことの証明にはなりません。

## #/teleop
ex-teleop-near-singular-prompt = 目標：関節の可動範囲の中で、可操作度 w が 0.001 m² 未満になる姿勢まで腕を動かしてください。
ex-teleop-near-singular-hint = w = l1·l2·|sin q2| を変えるのは肘の角度 q2 だけです。腕をゆっくり伸ばして（または折りたたんで）みましょう。
ex-teleop-near-singular-explain = q2 = 0 の近くでは腕はほぼまっすぐで、w は 0 に近づき、腕に沿った向きの手先の指令にはどんどん大きな関節速度が必要になります。
ex-teleop-which-joint-prompt = 3R アームが特異かどうかを決めるのは、どの関節の角度でしょう。
ex-teleop-which-joint-hint = J の隣り合う列を引き算してみましょう：det J = l1·l2·sin q2 です。
ex-teleop-which-joint-explain = det J = l1·l2·sin q2 なので、決めるのは肘だけです。肩は腕全体を回し、手首の列は他の列から引き算で消せるので行列式に残りません。
ex-teleop-which-joint-choice-1 = 肩（q1）
ex-teleop-which-joint-why-1 = q1 は腕全体を回すだけで、w はどの q1 でも同じです。
ex-teleop-which-joint-choice-2 = 肘（q2）
ex-teleop-which-joint-why-2 = 正解：det J = l1·l2·sin q2 は q2 = 0 と q2 = ±π で 0 になります。
ex-teleop-which-joint-choice-3 = 手首（q3）
ex-teleop-which-joint-why-3 = 手首の列を他の列から引くと行列式から l3 が消えるので、q3 は行列式を変えません。
ex-teleop-calm-method-prompt = 腕がほぼまっすぐなとき、同じ小さな手先の指令を pinv と DLS に与えます。関節の動きが小さいのはどちらでしょう。
ex-teleop-calm-method-hint = pinv は J をそのまま逆行列にし、DLS は逆行列を取る前に J Jᵀ に λ² を足します。
ex-teleop-calm-method-explain = 特異点の近くでは J⁻¹ が 1/σ_min のように大きくなるので、pinv は巨大な関節の動きを求めます。DLS の λ² は J Jᵀ + λ² I を特異から遠ざけ、手先のわずかな追従誤差と引き換えに関節を落ち着かせます。
ex-teleop-calm-method-choice-1 = pinv
ex-teleop-calm-method-why-1 = 動きは 1/σ_min のように大きくなります。減衰がないので、特異点の近くでそれを抑えるものがありません。
ex-teleop-calm-method-choice-2 = DLS
ex-teleop-calm-method-why-2 = 正解：減衰 λ² が関節の動きを抑えます。代わりに手先の動きにわずかな誤差が出ます。
ex-teleop-calm-method-choice-3 = どちらも同じ
ex-teleop-calm-method-why-3 = 特異点から遠く、λ² が J Jᵀ に比べて小さいところでは一致しますが、特異点の近くでは何桁も違います。

## #/so101
ex-so101-low-w-prompt = 目標：すべての関節を可動範囲に収めたまま、SO-101 を可操作度 w が 0.001 m³ 未満になる姿勢にしてください。
ex-so101-low-w-hint = w は腕が伸び切ったり折りたたまれたりしたところで小さくなります。肘を大きく曲げてみましょう。
ex-so101-low-w-explain = 肘を折りたたむと、ツールが動ける方向がつぶれます。速度楕円体の 1 方向が縮み、その体積 w も小さくなります。
ex-so101-pan-prompt = 他の関節はそのままで、肩の旋回（関節 1）を回します。w はどうなるでしょう。
ex-so101-pan-hint = 旋回関節は腕全体を鉛直軸まわりに回します。
ex-so101-pan-explain = 腕全体を鉛直軸まわりに回すと、速度楕円体も形を変えずに一緒に回るので、w は変わりません。
ex-so101-pan-choice-1 = 変わらない
ex-so101-pan-why-1 = 正解：旋回は腕を剛体として回すだけで、回した楕円体の体積は同じです。
ex-so101-pan-choice-2 = 腕が横を向くほど大きくなる
ex-so101-pan-why-2 = 旋回で変わるのは腕の向きだけで、腕の形は何も変わりません。
ex-so101-pan-choice-3 = ±90° で 0 になる
ex-so101-pan-why-3 = 特異な姿勢は腕の形（伸び切り、折りたたみ）から生じ、向いている方向からは生じません。
ex-so101-five-joints-prompt = SO-101 の関節は 5 つ、ツールの姿勢は 6 つの数（x、y、z と 3 つの角度）です。ここから何が言えるでしょう。
ex-so101-five-joints-hint = 6×5 のヤコビアンの列を数えましょう。5 つの関節速度で、独立なツールの動きはいくつ作れるでしょう。
ex-so101-five-joints-explain = 5 つの関節速度で作れる独立なツールの動きは 6 つのうち多くて 5 つです。J Jᵀ（6×6）はどの姿勢でも特異なので、どの位置にも取れない向きがあり、IK は指令された動きにその 5 つで近づけることしかできません。
ex-so101-five-joints-choice-1 = 届く範囲なら、どの位置でもどの向きでも取れる
ex-so101-five-joints-why-1 = それには独立な動きが 6 つ必要ですが、5 つの関節では多くて 5 つです。
ex-so101-five-joints-choice-2 = どの位置でもどの向きでも取れるわけではない：ツールの動きの 1 方向が常に欠けている
ex-so101-five-joints-why-2 = 正解：6×5 のヤコビアンの階数は多くても 5 です。
ex-so101-five-joints-choice-3 = 関節が 1 つ余っている（冗長である）
ex-so101-five-joints-why-3 = 冗長な腕とは、タスクの数より関節が多い腕のことです。この腕は少ないほうです。

## ページの演習セクション（src/ui/exercises）
exercises-lede = まず予想し、それから確かめます。答えを判定するのはこのページ自身のカーネルです。{ $total } 問中 { $done } 問完了。
exercise-kind-predict = 予想
exercise-kind-goal = 目標
exercise-kind-choose = 選択
exercise-state-open = 未着手
exercise-state-predicting = 予想中
exercise-state-wrong = もう一度
exercise-state-right = 正解
exercise-state-revealed = 答えを表示
exercise-state-done = 完了
exercise-prediction-label = あなたの予想
exercise-commit = 確かめる
exercise-hint = ヒント
exercise-reveal = 答えを見る
exercise-again = もう一度挑戦
exercise-prediction-empty = まず数値を入力してください。
exercise-prediction-comma = 小数は点で書いてください（0.5）。コンマは使えません。
exercise-prediction-not-a-number = 数値ではありません。0.25、−3、1e-3 のように入力してください。
exercise-verdict-wrong = あなたの { $value } は{ $direction ->
    [high] 大きすぎます
   *[low] 小さすぎます
}。ページの値の { $tolerance } の範囲に入っていません。ヒントを読んで、もう一度どうぞ。
exercise-verdict-right = 正解です。あなたの { $value } に対してページの値は { $truth }（{ $tolerance } の範囲内）。
exercise-verdict-revealed = ページの値は { $truth } です。あなたの { $value } は { $tolerance } の範囲に入っていません。
exercise-verdict-shown = ページの値は { $truth } です。
exercise-no-truth = いまのページの状態には、この問題で比べる値がありません（実行が短すぎる、ゴールに届いていないなど）。状態を変えてから、もう一度どうぞ。
exercise-check-failed = いまのページの状態では確かめられません：{ $detail }
exercise-choice-right = 正解です。{ $why }
exercise-choice-wrong = これではありません。{ $why }
exercise-choice-revealed = 答えは「{ $choice }」です。{ $why }
exercise-goal-open = まだ達成していません。上のページを操作して達成してください。
exercise-goal-met-by-link = このページはリンクで開いた時点でこの目標を満たしています。目標を満たしたまま、ページのどこかを変えると達成として記録されます。
exercise-goal-done = 達成しました。
exercise-done-first-try = 完了（1 回目で正解）。
exercise-done-later = 完了。
