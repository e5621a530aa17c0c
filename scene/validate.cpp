#include "scene/validate.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "util/excerpt.h"

namespace villa::scene {
namespace {

std::string Quoted(std::string_view s) {
  std::string out(1, '"');
  out.append(Excerpt(s));
  out.push_back('"');
  return out;
}

// "<room>/<category>-<k>": true when `id` is exactly that for some k >= 0 written without leading zeros.
bool IdHasForm(const SceneObject& o) {
  std::string prefix = o.room + "/" + o.category + "-";
  if (o.id.size() <= prefix.size() || o.id.compare(0, prefix.size(), prefix) != 0) return false;
  std::string_view k = std::string_view(o.id).substr(prefix.size());
  if (k.size() > 1 && k[0] == '0') return false;
  return std::all_of(k.begin(), k.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// The relations a parent kind allows.
bool RelationFitsParent(Relation relation, std::string_view parent) {
  switch (relation) {
    case Relation::kOnTop: return parent == kParentFloor || !IsRootParent(parent);
    case Relation::kInside: return !IsRootParent(parent);
    case Relation::kAgainstWall: return parent == kParentFloor;
    case Relation::kOnWall: return parent == kParentWall;
    case Relation::kHanging: return parent == kParentCeiling;
  }
  return false;
}

class Checker {
 public:
  Checker(const SceneFile& scene, const Layout& layout, const AssetLookup& lookup, const ValidateOptions& options)
      : scene_(scene), layout_(layout), lookup_(lookup), options_(options) {
    for (const SceneObject& o : scene_.objects) by_id_.emplace(o.id, &o);
  }

  std::vector<Finding> Run() {
    Rooms();
    std::set<std::string> seen;
    for (const SceneObject& o : scene_.objects) {
      if (!seen.insert(o.id).second) Add(o.id, "id", "the id is used by more than one object");
      Object(o);
    }
    Forest();
    for (const RoomEntry& room : scene_.rooms) Edges(room);
    return std::move(findings_);
  }

 private:
  void Add(const std::string& subject, const std::string& rule, const std::string& message) {
    findings_.push_back({subject, rule, message});
  }

  void Rooms() {
    std::set<std::string> listed;
    for (const RoomEntry& room : scene_.rooms) {
      if (!listed.insert(room.name).second) Add(room.name, "rooms", "the room is listed twice");
      if (layout_.FindRoom(room.name) < 0) Add(room.name, "rooms", "not a room of the layout");
    }
    if (!options_.all_rooms) return;
    for (const Room& room : layout_.rooms)
      if (!listed.count(room.name())) Add(room.name(), "rooms", "a room of the layout is missing from `rooms`");
  }

  const AssetRecord* Asset(const std::string& id) const { return lookup_ && !id.empty() ? lookup_(id) : nullptr; }

  void Object(const SceneObject& o) {
    if (!IdHasForm(o))
      Add(o.id, "id", "expected " + Quoted(o.room + "/" + o.category + "-<k>") + " (its room and category)");
    int room = layout_.FindRoom(o.room);
    if (room < 0) {
      Add(o.id, "room", "room " + Quoted(o.room) + " is not in the layout");
    } else if (layout_.rooms[room].level != o.level) {
      Add(o.id, "room", "level " + std::to_string(o.level) + " but room " + Quoted(o.room) + " is on level " +
                            std::to_string(layout_.rooms[room].level));
    }
    if (!scene_.FindRoom(o.room)) Add(o.id, "room", "room " + Quoted(o.room) + " is not listed in `rooms`");

    bool attached = o.relation == Relation::kOnWall || o.relation == Relation::kHanging;
    if (!attached && !(o.affordances & kConsumer))
      Add(o.id, "physical-edge", "rests on " + Quoted(o.parent) + " but is not V_con");
    if (!RelationFitsParent(o.relation, o.parent))
      Add(o.id, "physical-edge", "relation " + std::string(RelationName(o.relation)) + " cannot have parent " + Quoted(o.parent));
    if (o.relation != Relation::kOnTop && o.surface) Add(o.id, "surface", "`surface` belongs to ontop objects only");
    if (o.relation == Relation::kOnTop && o.parent == kParentFloor && o.surface)
      Add(o.id, "surface", "an object on the floor names no surface");
    if (o.relation != Relation::kInside && o.cavity) Add(o.id, "cavity", "`cavity` belongs to inside objects only");
    bool walled = o.relation == Relation::kAgainstWall || o.relation == Relation::kOnWall;
    if (!walled && o.wall) Add(o.id, "wall", "`wall` belongs to against_wall and on_wall objects only");
    if (walled && o.pose && !o.wall) Add(o.id, "wall", "a posed " + std::string(RelationName(o.relation)) + " object names its wall edge");
    if (o.wall && room >= 0 && o.wall->edge >= static_cast<int>(layout_.rooms[room].polygon.size()))
      Add(o.id, "wall", "wall edge " + std::to_string(o.wall->edge) + " but room " + Quoted(o.room) + " has " +
                            std::to_string(layout_.rooms[room].polygon.size()) + " edges");

    if (!IsRootParent(o.parent)) Parent(o);

    const AssetRecord* asset = Asset(o.asset);
    if (lookup_ && !o.asset.empty() && !asset) Add(o.id, "asset", "asset " + Quoted(o.asset) + " is not in the library");
    if ((o.affordances & kProvider) && asset && asset->support_surfaces.empty() && asset->cavities.empty())
      Add(o.id, "asset", "V_pro but asset " + Quoted(o.asset) + " has no support surface and no cavity");

    if (o.interaction_zone) {
      if (!(o.affordances & kInteractor)) Add(o.id, "zone", "has an interaction zone but is not V_int");
      for (const std::string& e : o.interaction_zone->exempt)
        if (!by_id_.count(e)) Add(o.id, "zone", "exempt object " + Quoted(e) + " does not exist");
    }
    for (const std::string& h : o.hints)
      if (!IsKnownHint(h)) Add(o.id, "hint", "unknown hint " + Quoted(h));
  }

  void Parent(const SceneObject& o) {
    auto it = by_id_.find(o.parent);
    if (it == by_id_.end()) return;  // reported by Forest()
    const SceneObject& p = *it->second;
    if (p.level != o.level)
      Add(o.id, "level", "level " + std::to_string(o.level) + " but its parent " + Quoted(p.id) + " is on level " +
                             std::to_string(p.level));
    if (!(p.affordances & kProvider)) Add(o.id, "provider", "parent " + Quoted(p.id) + " is not V_pro");
    const AssetRecord* asset = Asset(p.asset);
    if (o.relation == Relation::kOnTop) {
      if (asset && o.pose && !o.surface) Add(o.id, "surface", "ontop " + Quoted(p.id) + " names no surface");
      if (asset && o.surface && *o.surface >= static_cast<int>(asset->support_surfaces.size()))
        Add(o.id, "surface", "surface " + std::to_string(*o.surface) + " but asset " + Quoted(p.asset) + " has " +
                                 std::to_string(asset->support_surfaces.size()));
    }
    if (o.relation == Relation::kInside) {
      if (asset && o.pose && !o.cavity) Add(o.id, "cavity", "inside " + Quoted(p.id) + " names no cavity");
      if (asset && o.cavity && *o.cavity >= static_cast<int>(asset->cavities.size()))
        Add(o.id, "cavity", "cavity " + std::to_string(*o.cavity) + " but asset " + Quoted(p.asset) + " has " +
                                std::to_string(asset->cavities.size()));
    }
  }

  // Parents form a forest rooted at floor / wall / ceiling: walk up from every object.
  void Forest() {
    for (const SceneObject& o : scene_.objects) {
      std::set<std::string> path = {o.id};
      const SceneObject* at = &o;
      while (!IsRootParent(at->parent)) {
        auto it = by_id_.find(at->parent);
        if (it == by_id_.end()) {
          Add(o.id, "forest", (at == &o ? "parent " : "ancestor " + Quoted(at->id) + " has parent ") +
                                  Quoted(at->parent) + (at == &o ? " does not exist" : ", which does not exist"));
          break;
        }
        if (!path.insert(it->first).second) {
          Add(o.id, "forest", "its parents form a cycle through " + Quoted(it->first));
          break;
        }
        at = it->second;
      }
    }
  }

  void Edges(const RoomEntry& room) {
    for (size_t i = 0; i < room.edges_sem.size(); ++i) {
      const SemanticEdge& e = room.edges_sem[i];
      std::string where = "edges_sem[" + std::to_string(i) + "] " + e.source + " " +
                          std::string(SemanticRelationName(e.relation)) + " " + e.target;
      for (const std::string* end : {&e.source, &e.target}) {
        auto it = by_id_.find(*end);
        if (it == by_id_.end()) Add(room.name, "edge", where + ": object " + Quoted(*end) + " does not exist");
        else if (it->second->room != room.name)
          Add(room.name, "edge", where + ": object " + Quoted(*end) + " is in room " + Quoted(it->second->room));
      }
      if (e.source == e.target) Add(room.name, "edge", where + ": an edge joins two different objects");
    }
  }

  const SceneFile& scene_;
  const Layout& layout_;
  const AssetLookup& lookup_;
  const ValidateOptions& options_;
  std::map<std::string, const SceneObject*> by_id_;
  std::vector<Finding> findings_;
};

}  // namespace

std::vector<Finding> ValidateScene(const SceneFile& scene, const Layout& layout, const AssetLookup& lookup,
                                   const ValidateOptions& options) {
  return Checker(scene, layout, lookup, options).Run();
}

std::string FormatFindings(const std::vector<Finding>& findings) {
  std::string out;
  for (const Finding& f : findings) out += f.subject + ": " + f.rule + ": " + f.message + "\n";
  return out;
}

}  // namespace villa::scene
