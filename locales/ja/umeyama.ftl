## Umeyama 法による位置合わせのページ（#/umeyama-2d）
umeyama-lede = umeyama-2d レシピの点群 X、ノイズを含む目標点 Y = s R X + t + ノイズ、そしてそこから Umeyama 法の閉じた形の解が求める相似変換です。点をドラッグする、何もない所をクリックして点を足す、紫のハンドルで真の並進と回転を変える、といった操作のあと、推定の手順を一歩ずつ進めてみてください。
umeyama-edited = 編集済み：点または真の相似変換がレシピのものと違うため、この実行は Python レシピとは一致しません。下のコマンドラインには、bsv で同じ結果を再現するオプションが入っています。umeyama_points.csv には X、Y、位置合わせ後の点が入ります。
umeyama-more-loading = ダウンロードとコマンドラインを読み込んでいます… 点の操作、推定結果、手順はもう使えます。
umeyama-more-failed = ダウンロードとコマンドラインを読み込めませんでした。ネットワークにつながっていません。点の操作、推定結果、手順、パラメータはそのまま使えます。接続を確かめてから、もう一度お試しください。
umeyama-view-title = 点群と推定結果
umeyama-canvas-label = 平面上に、元の点 X（青い円、番号順）、ノイズを含む目標点 Y（オレンジの四角）、位置合わせ後の点 s R X + t（緑の輪）、残差（赤い破線）、真の並進と回転のハンドル（紫）を表示しています。キー：右矢印で次の手順、左矢印で前の手順、n で次の点を選択（Shift + n で前の点）、Shift + 矢印キーで選んだ点を移動、Delete でその点を削除、a で点を追加。
umeyama-legend-x = X：元の点（ドラッグ可）
umeyama-legend-y = Y：ノイズを含む目標点
umeyama-legend-aligned = 位置合わせ後：s R X + t
umeyama-legend-residual = 残差
umeyama-legend-truth = 真の t と s·R（ドラッグ可）
umeyama-action-add = 点を追加
umeyama-action-remove = 選んだ点を削除
umeyama-action-mirror = 鏡映のプリセット
umeyama-action-recipe = レシピの点と真値に戻す
umeyama-view-note = 何もない所をクリック（タップ）すると、そこに点が加わります（最大 40 個）。点はクリックで選べます。各点には、リスト上の位置に応じたレシピのノイズがそのまま使われるので、1 つの点を動かしても変わるのはその点の目標点だけです。
umeyama-refused-too-many = 点はすでに { $count } 個あり、このページで扱える上限です。
umeyama-refused-too-few = 相似変換には少なくとも { $count } 個の点が必要なので、この点は残します。
umeyama-png = 表示を保存（PNG）
umeyama-key-delete = 選んだ点を削除
umeyama-key-add = 点を追加
umeyama-key-select = 次の点を選ぶ。最後の点の次は平行移動のハンドル t、その次は回転のハンドル s·R（Shift + n で前へ）
umeyama-key-move = 選んだ点または t を 0.01 ずつ動かす（ドラッグと同じ）。s·R は ← → で 0.5° ずつ回し、↑ ↓ で 0.01 ずつ拡大縮小
umeyama-selected = 点 { $n }（全 { $count } 点）を選択中：位置 ({ $x }, { $y })。Shift + 矢印キーで 0.01 ずつ動かし、Delete で削除できます。
umeyama-selected-translation = 平行移動のハンドル t を選択中：位置 ({ $x }, { $y })。Shift + 矢印キーで 0.01 ずつ動かせます。
umeyama-selected-rotation = 回転のハンドル s·R を選択中：角度 { $angle }°、スケール { $scale }。Shift + ← → で 0.5° ずつ回し、Shift + ↑ ↓ で 0.01 ずつ拡大縮小できます。
umeyama-selected-none = 点は選ばれていません（全 { $count } 点）。n で次の点を、Shift + n で前の点を選べます。
umeyama-live = 推定：スケール { $scale }、角度 { $angle }°、rmse { $rmse }。
umeyama-ro-title = 推定値と真値
umeyama-ro-estimate = 推定値
umeyama-ro-truth = 真値
umeyama-ro-scale = スケール s
umeyama-ro-angle = 角度（°）
umeyama-ro-tx = 並進 tx
umeyama-ro-ty = 並進 ty
umeyama-ro-rmse = rmse（真値の列は σ√2）
umeyama-ro-note = 推定値は CSV の数値と最後の桁まで同じです。rmse の真値の列は、ノイズだけで生じる 1 点あたりの大きさ σ√2 です。
umeyama-speed = { $seconds } 秒ごとに 1 手順
umeyama-step-overview-title = 推定の全体像
umeyama-step-overview-text = Y は X に真の相似変換をかけてノイズを加えたものです。推定では、最小二乗の意味で X を Y に最も近づける s、R、t を求めます。緑の輪が s R X + t です。次の手順へ進むと、その求め方が見られます。
umeyama-step-centroids-title = 重心
umeyama-step-centroids-text = まず両方の点群の平均、X の μx と Y の μy を求めます。並進は最後に、この 2 点から決まります。
umeyama-step-centred-title = 重心を引いた点群
umeyama-step-centred-text = 平均を引くと、両方の点群が原点に移ります：Xc = X − μx、Yc = Y − μy。あとは回転とスケールを合わせるだけです。var_x は Xc の長さの 2 乗の平均です。
umeyama-step-covariance-title = 相互共分散行列
umeyama-step-covariance-text = C = Ycᵀ Xc / n は、各組について目標点が元の点とどう並ぶかを足し合わせたものです。その列（青緑の矢印）は、C が 2 本の座標軸をどこへ移すかを表します。det C が負なら、Y は X を鏡に映したように見えます。
umeyama-step-svd-title = 特異値分解
umeyama-step-svd-text = C = U S Vᵀ：C は V の各軸 v_k（青）を S_k u_k（オレンジ）に移します。最良の回転は U Vᵀ で、各 v_k を u_k に重ねます。
umeyama-step-reflection-title = 鏡映の補正
umeyama-step-reflection-none = det(U Vᵀ) = +1：U Vᵀ はすでに回転なので、補正は要りません。補正の様子は鏡映のプリセットで確かめられます。
umeyama-step-reflection-fixed = det(U Vᵀ) = −1：U Vᵀ は鏡映になってしまい、回転ではありません。レシピは U の最後の列の符号を反転し（赤い破線の矢印が元の列）、R = U′Vᵀ を C に最も近い回転にします。
umeyama-step-scale-title = スケール
umeyama-step-scale-text = s = (S₁ + S₂) / var_x：回転で合わせたあと、目標点が元の点よりどれだけ大きく広がっているかを表します。円の半径は μx のまわりが √var_x、μy のまわりが s √var_x です。
umeyama-step-scale-quirk = s = (S₁ + S₂) / var_x = { $recipe }。鏡映を補正したとき、本来の Umeyama 法なら S₁ − S₂ を使って { $umeyama } になりますが、レシピは和のままにします（レシピの癖）。
umeyama-step-translation-title = 並進
umeyama-step-translation-text = t = μy − s R μx：回転とスケールをかけた元の点（薄い緑）を、s R μx から μy への矢印で目標点の上へ運びます。
umeyama-step-rmse-title = 残差
umeyama-step-rmse-text = rmse = √(Σ |s R Xᵢ + t − Yᵢ|² / n)、赤い残差の大きさです。各座標のノイズが σ ならおよそ σ√2 になります。点が 2 個だけなら、ノイズに関係なく 0 です。
umeyama-explain-what-title = レシピがすること
umeyama-explain-what = umeyama_align_2d.py は numpy の default_rng(seed) で n 個の点 X を作り、目標点 Y = 1.3 R(35°) X + (0.4, −0.2) に標準偏差 σ のガウスノイズを加えます。そこから Umeyama 法の閉じた形の解で、スケール、回転角、並進を推定します。CSV には推定値と真値が並びます。既定値（0.02 3 12）なら、スケールはおよそ 1.3、角度はおよそ 35° になります。
umeyama-explain-steps-title = なぜうまくいくのか
umeyama-explain-steps = 重心を引くと、並進をほかの部分から切り離せます。相互共分散行列 C は、重心を引いた目標点が元の点とどう並ぶかを集めたものです。すべての回転のうち、この並びを最もよくそろえるのが C の特異値分解から得られる U Vᵀ です。スケールは、回転で説明できる広がりと元の点自身の広がりの比で、最後に並進で重心を合わせます。
umeyama-explain-reflection-title = 鏡映について
umeyama-explain-reflection = 目標点が元の点の鏡像になっている場合（鏡映のプリセット）、U Vᵀ は鏡映（det −1）になります。回転では鏡映を表せないため、レシピは U の最後の列を反転して最も近い回転にします。それでも当てはまりは悪いままで、rmse の大きさにそれが表れます。
umeyama-explain-edit-title = 実行内容を編集する
umeyama-explain-edit = 追加したり動かしたりした点や、変更した真の相似変換は、bsv umeyama-2d のオプション（--x、--scale、--angle、--tx、--ty、--mirror）になります。オプションがなければ、実行結果は Python レシピとバイト単位で同じです。乱数はレシピと同じ順序で引くので、i 番目の点には常にレシピの i 番目の点と同じノイズが加わります。
umeyama-explain-recipe-title = レシピのコード（BSV オリジナル、MIT ライセンス）
umeyama-explain-recipe = 入力：sigma seed n（既定値 0.02 3 12）。出力：推定したスケール、rotation_deg、tx、ty、rmse と、真のスケールと回転を並べた umeyama_2d.csv。研究・教育用です。推定の部分は、レシピでは次のとおりです。
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
