# 学習者の進み具合（src/view/learner_progress、src/ui/kit/progress_panel）：進み具合のファイルの問題、
# そのパネル（名前・書き出し・読み込み）、ホームの進み具合、クラスのページ（#/class、
# src/view/class_summary）。演習セクション、ホームの進み具合、#/class と一緒に読み込まれ、どの
# ページの最初の読み込みにも入らない。

## 学習者の進み具合のファイル（bsv_progress.json）
progress-error-not-text = このファイルは進み具合として読めませんでした：{ $detail }
progress-error-too-big = このファイルは { $size }（{ $bytes } バイト）あります。進み具合のファイルは { $limit } までです。ファイルは読み込んでいません。
progress-error-empty-file = このファイルは空です。
progress-error-too-deep = このファイルはリストやオブジェクトの入れ子が { $max } 段を超えています（{ $line } 行目、{ $column } 文字目）。進み具合のファイルの入れ子は 3 段です。
progress-error-not-json = このファイルは JSON ではありません：{ $line } 行目、{ $column } 文字目で読めなくなります。
progress-error-not-an-object = この JSON ファイルの中身は{ $kind ->
    [array] リスト
    [text] 文字列
    [number] 数値
    [boolean] true か false
    *[other] null
}で、進み具合の記録ではありません。
progress-error-no-format = この JSON ファイルは BSV の進み具合のファイルではありません：「format」フィールドがありません（進み具合のファイルには "format": "bsv-progress" があります）。
progress-error-format = このファイルは BSV の進み具合のファイルではありません（形式「{ $found }」、期待される形式は「bsv-progress」）。
progress-error-version = この進み具合のファイルは別のバージョン（バージョン { $found }）で作られています。このアプリが読めるのはバージョン { $version } です。
progress-error-unknown-field = 進み具合のファイルに、このアプリが知らないフィールド「{ $field }」があります。
progress-error-exercise-unknown-field = 演習 { $exercise } に、このアプリが知らないフィールド「{ $field }」があります。
progress-error-missing-field = 進み具合のファイルに「{ $field }」フィールドがありません。
progress-error-exercise-missing-field = 演習 { $exercise } に「{ $field }」フィールドがありません。
progress-error-wrong-type = 進み具合のファイルのフィールド「{ $field }」は{ $expected ->
    [text] 文字列
    [number] 整数
    [boolean] true か false
    *[list] 演習のリスト
}でなければなりません。
progress-error-exercise-wrong-type = 演習 { $exercise }、フィールド「{ $field }」：{ $expected ->
    [text] 文字列
    [number] 整数
    [boolean] true か false
    *[list] リスト
}でなければなりません。
progress-error-exercise-not-an-object = 演習 { $exercise } が、id と試行回数を持つオブジェクトではありません。
progress-error-too-many-exercises = 進み具合のファイルに入る演習は { $max } 個までです。このファイルには { $count } 個あります。
progress-error-bad-id = 演習 { $exercise }：「{ $id }」は演習の id ではありません。
progress-error-duplicate-id = 演習「{ $id }」が 2 回出てきます。
progress-error-attempts = 演習 { $exercise }：試行回数がこのアプリの数えられる範囲を超えています。
progress-error-inconsistent = 演習「{ $id }」の記録のつじつまが合いません：完了には 1 回以上の試行が、初回正解には完了が必要です。
progress-error-name-too-long = 学習者の名前は { $max } 文字までです。
progress-error-build-too-long = フィールド「build」が { $max } 文字を超えています。

## クラスのまとめ（#/class）
class-duplicate = { $learner } さんの 2 つ目のファイルです（1 つ目は { $first }）。{ $same ->
    [same] 進み具合が同じなので、表には入れていません。
    *[different] 進み具合が違います。表には入れず、1 つ目のファイルの進み具合を表示しています。
}

## 進み具合のパネル（各ページの演習セクション、ホーム）
progress-name-label = あなたの名前（任意。書き出すファイルに入ります）
progress-export = 進み具合を書き出す
progress-import = 進み具合を読み込む
progress-imported = { $file }：{ $count } 問の記録をあなたの進み具合にまとめました。
progress-imported-unknown = { $file }：{ $count } 問の記録をあなたの進み具合にまとめました。新しいバージョンのアプリの演習 { $unknown } 問の記録もそのまま残してあります。
progress-file-problem = { $file }：{ $problem }
progress-not-saved = このブラウザーは進み具合を保存しません（ストレージがオフです）。ページを離れる前に書き出してください。
progress-not-saved-full = このブラウザーのストレージがいっぱいで、進み具合を保存できません。ページを離れる前に書き出してください。

## ホームの進み具合
home-progress-heading = あなたの演習
home-progress-intro = どのドリルのページも最後に演習があります。まず予想し、ページ自身の数値で確かめましょう。進み具合はこのブラウザーに保存されます。先生に出すときは書き出し、別の端末では読み込んでください。
home-progress-page = { $done } / { $total }
home-progress-page-label = { $page }：{ $total } 問中 { $done } 問完了
home-progress-class = 先生へ：クラスの進み具合のファイルは「クラス」のページでまとめて開けます →

## クラスのページ（#/class）
class-title = クラスの進み具合
class-lede = 学習者の bsv_progress.json を、何個でもまとめて開くか、ここにドロップしてください。誰がどこまで終えたかの表と、演習ごとの正答率が出ます。データはこのブラウザーの外に出ません。
class-files-label = 進み具合のファイル
class-pick = 進み具合のファイルを開く
class-clear = クリア
class-drop = 進み具合のファイルをここにドロップ
class-empty = まだ進み具合のファイルを開いていません。
class-counts = 学習者 { $learners } 人、表に入れなかったファイル { $files } 個。
class-rejected-heading = 表に入れなかったファイル
class-table-heading = 学習者と演習
class-table-caption = ✓ 1 回目で正解、◐ あとで正解、· まだ。
class-learner = 学習者
class-file = ファイル
class-standing-first-try = 1 回目で正解
class-standing-later = あとで正解
class-standing-not-yet = まだ
class-unknown-ids = 新しいバージョンの演習ほか { $count } 問
class-rates-heading = 演習（難しい順）
class-rate-exercise = 演習
class-rate-page = ページ
class-rate-success = 完了
class-rate-first-try = 1 回目で正解
class-rate-value = { $rate } %
class-download = まとめをダウンロード（CSV）
