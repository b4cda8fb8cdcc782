# ホームページ：BSV ページの見出しと紹介文、ブラウザで動く注目のツール、各レシピのカード
# （レシピ自体の文言は recipes.ftl にある）。

home-page-title = ホーム
home-headline = ロボティクス：シミュレーションし、サンプリングし、記録する。そして遠隔操作の練習へ
home-intro = 短く、ごまかしのないシミュレーション演習を組み立てましょう。題材は MuJoCo のエネルギー、平面 IK、軌道のリサンプリング、DH 順運動学、ヤコビアンと可操作度、3 次の関節経路、SE(3) の相対姿勢、そして簡易版の 2D RRT です。Isaac Teleop による遠隔操作の練習には Robot Pilot Academy を使ってください。BSV は NVIDIA のコードを再配布していません。
home-featured-label = ブラウザで動くインタラクティブなツール（英語／日本語）
home-featured-open = プレイグラウンドを開く
home-recipes-heading = 演習レシピ
home-recipes-intro = BSV の Python レシピを Rust で作り直した、12 の短い演習です。コマンドラインの「bsv <レシピ ID>」は、Python スクリプトと同じ値を受け取り、同じ CSV ファイルを書き出します。
home-card-inputs = 入力と既定値
home-card-writes = 出力ファイル
home-card-options = オプション
home-card-cli = コマンドライン
home-card-python = 元の Python
home-card-drill = このドリルを実行する
home-card-in-browser = ブラウザで試す：
home-card-pairs-ik-2r = IK プレイグラウンド（BSV の元の資料では「IK Field Lab」と呼ばれているもの）と組み合わせて使えます。そこでアームを動かすと |det J| の変化が見られます。
home-card-pairs-traj-resample = 専用のページでそのまま動かせます。CSV を開くかドロップすると、各関節のリサンプリング結果が見られます。
home-card-pairs-cubic-path = 3 次経路のページと組み合わせて使えます。終点と終了時刻をドラッグすると、速度と加速度の変化が見られます。
home-card-pairs-pid-step = PID ステップ応答のページと組み合わせて使えます。前のゲインの残像と並べて、Kp・Ki・Kd をその場で調整できます。
home-card-pairs-trapezoid-profile = 台形プロファイルのページと組み合わせて使えます。vmax と amax をドラッグし、動きが三角形になる境目を確かめられます。
home-card-pairs-pendulum-energy = 振り子のページと組み合わせて使えます。振れる様子を見ながら、Euler と RK4 を並べてエネルギーのずれを比べられます。
home-card-pairs-rrt-2d = RRT ステッパーと組み合わせて使えます。自分で描いた環境で、木を 1 反復ずつ（逆向きにも）成長させられます。
home-card-pairs-umeyama-2d = Umeyama 法のページと組み合わせて使えます。点と真の変換をドラッグし、重心、共分散、特異値分解、鏡映の補正、スケール、並進を一歩ずつ確かめられます。
