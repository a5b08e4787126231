# The routed die as a picture (scripts/flows/layout/layout.sh; docs/silicon/layout.md "Layout: placed, routed, DRC and LVS checked"): KLayout in
# batch mode reads the routed DEF with the cells' and macros' LEF and writes a PNG, each
# metal in its colour, the macros and cells as outlines, and the blocks of Fig. 1 framed
# and named where the placement put them (layout_summary.json's boxes, from the instance
# names).
#   klayout -b -rd def=ROUTED.def -rd lefs=A.lef,B.lef -rd summary=layout_summary.json \
#           -rd png=OUT.png [-rd width=2000] -r layout_picture.rb
require 'json'

opt = RBA::LoadLayoutOptions.new
opt.lefdef_config.lef_files = $lefs.split(",")
ly = RBA::Layout.new
ly.read($def, opt)
top = ly.top_cell
dbu = ly.dbu

# the blocks of Fig. 1: a frame and a name each, on a layer of their own
summary = JSON.parse(File.read($summary))
frames = ly.layer(RBA::LayerInfo.new(200, 0, "blocks"))
(summary["blocks"] || {}).each do |name, b|
  x0, y0, x1, y1 = b["box_5_95_um"]
  next if x1 - x0 < 1 || y1 - y0 < 1
  box = RBA::DBox.new(x0, y0, x1, y1)
  top.shapes(frames).insert(RBA::DPath.new([box.p1, RBA::DPoint.new(x0, y1), box.p2,
                                           RBA::DPoint.new(x1, y0), box.p1], 0.004 * [summary["die_um"][0], summary["die_um"][1]].max))
  top.shapes(frames).insert(RBA::DText.new(name, RBA::DTrans.new(box.center.x, box.center.y)))
end
(summary["macros"] || []).each do |m|
  c = RBA::DPoint.new(m["x_um"] + m["w_um"] / 2, m["y_um"] + m["h_um"] / 2)
  top.shapes(frames).insert(RBA::DText.new(m["instance"].split(".")[0] + " " + m["cell"], RBA::DTrans.new(c.x, c.y)))
end

view = RBA::LayoutView.new
view.set_config("background-color", "#ffffff")
view.set_config("text-font", "0")
view.set_config("default-text-size", "0")
view.set_config("text-color", "#000000")
view.set_config("grid-visible", "false")
idx = view.show_layout(ly, false)
view.max_hier
view.add_missing_layers
colours = { "metal1" => 0xff1f77b4, "metal2" => 0xffd62728, "metal3" => 0xff2ca02c, "metal4" => 0xffff7f0e,
            "metal5" => 0xff9467bd, "metal6" => 0xff8c564b, "OUTLINE" => 0xff7f7f7f, "blocks" => 0xff000000 }
it = view.begin_layers
while !it.at_end?
  lp = it.current
  info = ly.get_info(lp.layer_index) rescue nil
  node = lp.dup
  if info
    name = info.name.to_s
    base = info.layer == 200 ? "blocks" : name.split(".")[0]
    if colours.key?(base) && !name.include?("LABEL") && !name.include?("PIN")
      node.fill_color = colours[base]
      node.frame_color = colours[base]
      node.dither_pattern = (base == "OUTLINE" || base == "blocks") ? 1 : 5
      node.width = base == "blocks" ? 2 : 1
      node.visible = true
    else
      node.visible = false
    end
  end
  view.set_layer_properties(it, node)
  it.next
end
view.zoom_fit
width = ($width || "2000").to_i
bbox = top.dbbox
height = (width * bbox.height / bbox.width).round
view.save_image($png, width, height)
puts "layout_picture.rb: #{$png} #{width} x #{height}"
