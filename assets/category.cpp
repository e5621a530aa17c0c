#include "assets/category.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace villa {
namespace {

constexpr unsigned kCon = kConsumer;
constexpr unsigned kConPro = kConsumer | kProvider;
constexpr unsigned kConInt = kConsumer | kInteractor;
constexpr unsigned kAll = kConsumer | kProvider | kInteractor;

InteractionZoneSpec Front(double depth) { return {"front", depth}; }

// Sizes from common furniture dimensions; zones from PRIORS.md's clearance table (seating 0.45, chair
// pull-out 0.6, drawers 0.5, doors of wardrobes and cabinets 0.8, appliances 1.0, beds 0.6 a side,
// toilet 0.6, basin 0.7).
std::vector<CategoryInfo> MakeTable() {
  using P = Placement;
  return {
      // ---- seating
      {"sofa", {"couch", "settee", "corner sofa", "futon"}, P::kFloor, {1.6, 0.8, 0.7}, {2.6, 1.0, 0.95}, kAll, true, false, Front(0.45), true, "sofa"},
      {"armchair", {"arm chair", "easy chair", "lounge chair", "relax chair"}, P::kFloor, {0.65, 0.7, 0.7}, {0.95, 0.95, 1.05}, kConInt, false, false, Front(0.45), false, "armchair"},
      {"chair", {"dining chair", "side chair", "seat", "visitor chair", "meeting chair"}, P::kFloor, {0.4, 0.45, 0.78}, {0.55, 0.6, 1.0}, kConInt, false, false, Front(0.6), false, "chair"},
      {"office-chair", {"desk chair", "swivel chair", "task chair"}, P::kFloor, {0.55, 0.55, 0.9}, {0.7, 0.7, 1.2}, kConInt, false, false, Front(0.6), false, "office-chair"},
      {"stool", {"bar stool", "counter stool", "tabouret", "bar chair", "ottoman", "puff", "pouf"}, P::kFloor, {0.32, 0.32, 0.45}, {0.45, 0.45, 0.8}, kCon, false, false, std::nullopt, false, "stool"},
      {"bench", {"piano bench"}, P::kFloor, {0.9, 0.35, 0.42}, {1.6, 0.5, 0.5}, kConPro, true, false, std::nullopt, false, "bench"},
      {"child-chair", {"kids chair", "children chair", "small chair", "high chair", "baby high chair"}, P::kFloor, {0.3, 0.3, 0.5}, {0.42, 0.42, 0.65}, kConInt, false, false, Front(0.4), false, "chair"},
      {"deck-chair", {"deckchair", "sun lounger", "pool lounge", "lounger"}, P::kFloor, {0.55, 1.2, 0.5}, {0.75, 1.9, 1.0}, kConInt, false, false, Front(0.4), false, "lounger"},
      {"outdoor-chair", {"garden chair", "patio chair", "cafe chair", "folding chair"}, P::kFloor, {0.42, 0.45, 0.78}, {0.6, 0.6, 0.95}, kConInt, false, false, Front(0.5), false, "chair"},
      // ---- tables and desks
      {"coffee-table", {"cocktail table", "low table"}, P::kFloor, {0.8, 0.45, 0.35}, {1.3, 0.8, 0.48}, kConPro, true, false, std::nullopt, false, "table"},
      {"side-table", {"end table", "lamp table", "occasional table"}, P::kFloor, {0.35, 0.35, 0.45}, {0.6, 0.6, 0.7}, kConPro, true, false, std::nullopt, false, "table"},
      {"dining-table", {"table", "tbl", "kitchen table", "dinner table", "round table"}, P::kFloor, {0.9, 0.75, 0.72}, {2.4, 1.1, 0.78}, kConPro, true, false, std::nullopt, false, "table"},
      {"conference-table", {"meeting table", "boardroom table"}, P::kFloor, {1.4, 0.9, 0.72}, {4.0, 1.4, 0.78}, kConPro, true, false, std::nullopt, false, "table"},
      {"desk", {"writing desk", "computer desk", "study desk", "work table", "desk table"}, P::kFloor, {1.0, 0.55, 0.72}, {1.8, 0.8, 0.78}, kAll, true, false, Front(0.6), true, "desk"},
      {"play-table", {"kids table", "children table", "activity table"}, P::kFloor, {0.6, 0.5, 0.45}, {1.0, 0.7, 0.55}, kConPro, true, false, std::nullopt, false, "table"},
      {"outdoor-table", {"garden table", "patio table", "cafe table", "bistro table"}, P::kFloor, {0.6, 0.6, 0.7}, {1.2, 0.9, 0.76}, kConPro, true, false, std::nullopt, false, "table"},
      {"island", {"kitchen island", "island extension"}, P::kFloor, {1.2, 0.6, 0.88}, {2.4, 1.0, 0.95}, kConPro, true, false, std::nullopt, false, "counter"},
      // ---- storage
      {"bookcase", {"bookshelf", "bookshelves", "book shelf", "shelving", "shelving unit", "shelf unit", "vertical shelves", "display rack", "shelves"}, P::kFloor, {0.6, 0.28, 1.2}, {1.2, 0.4, 2.1}, kAll, true, true, Front(0.5), true, "bookcase"},
      {"wardrobe", {"closet", "armoire", "clothes cabinet"}, P::kFloor, {0.9, 0.55, 1.8}, {2.0, 0.65, 2.3}, kAll, true, true, Front(0.8), true, "wardrobe"},
      {"dresser", {"chest of drawers", "drawers cabinet", "drawer chest", "commode", "dressing table", "changing table"}, P::kFloor, {0.7, 0.4, 0.75}, {1.4, 0.55, 1.1}, kAll, true, true, Front(0.5), true, "dresser"},
      {"nightstand", {"bedside table", "night table", "bedside cabinet"}, P::kFloor, {0.4, 0.35, 0.45}, {0.6, 0.45, 0.65}, kAll, true, true, Front(0.3), true, "nightstand"},
      {"piano", {"upright piano", "grand piano", "digital piano", "pianoforte"}, P::kFloor, {1.3, 0.5, 1.05}, {1.6, 0.7, 1.35}, kAll, true, false, Front(0.9), true, "piano"},
      {"tv-stand", {"television cabinet", "tv cabinet", "media console", "tv unit", "tv bench"}, P::kFloor, {1.2, 0.38, 0.4}, {2.0, 0.5, 0.6}, kAll, true, true, Front(0.5), true, "tv-stand"},
      {"sideboard", {"buffet", "credenza", "low cabinet"}, P::kFloor, {1.2, 0.4, 0.7}, {2.0, 0.5, 0.9}, kAll, true, true, Front(0.8), true, "cabinet"},
      {"glass-cabinet", {"glass door cabinet", "display cabinet", "vitrine", "china cabinet"}, P::kFloor, {0.8, 0.38, 1.6}, {1.2, 0.5, 2.0}, kAll, true, true, Front(0.8), true, "glass-cabinet"},
      {"cabinet", {"cupboard", "storage cabinet", "bathroom cabinet", "high cabinet", "locker"}, P::kFloor, {0.5, 0.35, 0.8}, {1.0, 0.6, 2.0}, kAll, true, true, Front(0.8), true, "cabinet"},
      {"filing-cabinet", {"file cabinet", "filing cabinets", "drawer unit"}, P::kFloor, {0.4, 0.5, 0.7}, {0.5, 0.65, 1.35}, kAll, true, true, Front(0.7), true, "dresser"},
      {"toy-chest", {"toy box", "chest", "trunk"}, P::kFloor, {0.6, 0.4, 0.4}, {1.0, 0.55, 0.6}, kAll, true, true, Front(0.5), true, "chest"},
      {"counter", {"lower cabinet", "base cabinet", "kitchen counter", "kitchen cabinet", "worktop", "sink cabinet", "lower corner cabinet", "small lower cabinet"}, P::kFloor, {0.6, 0.6, 0.88}, {2.4, 0.65, 0.92}, kAll, true, true, Front(1.0), true, "counter"},
      {"upper-cabinet", {"wall cabinet", "upper shelves cabinet", "kitchen wall cabinet", "upper corner cabinet", "small upper cabinet"}, P::kWall, {0.4, 0.33, 0.6}, {1.2, 0.38, 0.9}, kConPro, true, true, std::nullopt, false, "wall-cabinet"},
      {"wall-shelf", {"floating shelf", "wall shelves"}, P::kWall, {0.6, 0.2, 0.04}, {1.2, 0.3, 0.3}, kConPro, true, false, std::nullopt, false, "wall-shelf"},
      // ---- beds (a bed is planned a double, 1.4 m wide or more; narrower, down to a single of 0.9 m, only where
      // no double stands clear of the doors: scene/planner.cpp BedFits)
      {"bed", {"double bed", "queen bed", "king bed", "single bed"}, P::kFloor, {0.9, 1.95, 0.5}, {2.0, 2.2, 1.2}, kAll, true, false, InteractionZoneSpec{"sides", 0.6}, true, "bed"},
      {"child-bed", {"kids bed", "children bed", "bunk bed", "baby bed", "crib", "cot"}, P::kFloor, {0.8, 1.5, 0.5}, {1.2, 2.05, 1.7}, kAll, true, false, InteractionZoneSpec{"sides", 0.6}, true, "bed"},
      // ---- kitchen and laundry appliances
      {"fridge", {"refrigerator", "large fridge", "freezer"}, P::kFloor, {0.55, 0.6, 1.4}, {0.9, 0.75, 2.0}, kConInt, false, false, Front(1.0), true, "fridge"},
      {"cooker", {"stove", "oven", "range", "double oven", "large stove", "cooktop"}, P::kFloor, {0.5, 0.55, 0.85}, {0.9, 0.65, 0.95}, kAll, true, false, Front(1.0), true, "cooker"},
      {"dishwasher", {"dish washer"}, P::kFloor, {0.45, 0.55, 0.82}, {0.6, 0.62, 0.88}, kConInt, false, false, Front(1.0), true, "dishwasher"},
      {"washing-machine", {"washer", "washing machine", "laundry machine"}, P::kFloor, {0.58, 0.55, 0.82}, {0.62, 0.65, 0.9}, kAll, true, false, Front(1.0), true, "washer"},
      {"dryer", {"tumble dryer", "clothes dryer"}, P::kFloor, {0.58, 0.55, 0.82}, {0.62, 0.65, 0.9}, kAll, true, false, Front(1.0), true, "washer"},
      {"range-hood", {"hood", "extractor hood", "cooker hood"}, P::kWall, {0.5, 0.4, 0.3}, {0.9, 0.55, 0.9}, kCon, false, false, std::nullopt, false, "range-hood"},
      {"water-heater", {"boiler", "hot water tank"}, P::kWall, {0.4, 0.35, 0.6}, {0.6, 0.5, 1.1}, kCon, false, false, std::nullopt, false, "water-heater"},
      {"water-cooler", {"water dispenser"}, P::kFloor, {0.3, 0.3, 0.9}, {0.4, 0.4, 1.2}, kConInt, false, false, Front(0.5), true, "water-cooler"},
      // ---- bathroom
      {"toilet", {"wc", "toilets unit", "lavatory"}, P::kFloor, {0.36, 0.55, 0.7}, {0.45, 0.75, 0.85}, kConInt, false, false, Front(0.6), true, "toilet"},
      {"washbasin", {"basin", "vanity", "sink unit", "bathroom sink", "lavabo", "small lavatory"}, P::kFloor, {0.45, 0.4, 0.8}, {1.2, 0.6, 0.95}, kAll, true, false, Front(0.7), true, "washbasin"},
      {"bathtub", {"bath", "tub"}, P::kFloor, {1.5, 0.7, 0.5}, {1.85, 0.9, 0.65}, kConInt, false, false, Front(0.6), true, "bathtub"},
      {"shower", {"shower stall", "shower cabin", "shower cubicle"}, P::kFloor, {0.8, 0.8, 2.0}, {1.2, 1.0, 2.2}, kConInt, false, false, Front(0.6), true, "shower"},
      {"towel-rack", {"towel rail", "towel holder", "towel bar"}, P::kWall, {0.4, 0.08, 0.1}, {0.8, 0.15, 0.9}, kCon, false, false, std::nullopt, false, "towel-rack"},
      {"laundry-basket", {"hamper", "laundry hamper", "clothes basket"}, P::kFloor, {0.35, 0.3, 0.45}, {0.55, 0.45, 0.65}, kCon, false, false, std::nullopt, false, "basket"},
      {"bin", {"dustbin", "trash can", "waste bin", "wastebasket"}, P::kFloor, {0.22, 0.22, 0.25}, {0.35, 0.35, 0.6}, kCon, false, false, std::nullopt, false, "basket"},
      // ---- lighting
      {"floor-lamp", {"standing lamp", "standard lamp", "floor light"}, P::kFloor, {0.25, 0.25, 1.4}, {0.5, 0.5, 1.85}, kCon, false, false, std::nullopt, false, "lamp"},
      {"table-lamp", {"bedside lamp", "lamp", "desk lamp", "reading lamp"}, P::kSurface, {0.15, 0.15, 0.25}, {0.35, 0.35, 0.55}, kCon, false, false, std::nullopt, false, "lamp"},
      {"wall-lamp", {"wall light", "wall lamp", "sconce", "wall spotlight", "porch light", "track lights"}, P::kWall, {0.06, 0.08, 0.08}, {0.6, 0.4, 0.6}, kCon, false, false, std::nullopt, false, "lamp"},
      {"ceiling-lamp", {"ceiling light", "pendant", "pendant lamp", "chandelier", "hanging light", "ceiling fan"}, P::kCeiling, {0.3, 0.3, 0.15}, {0.9, 0.9, 0.7}, kCon, false, false, std::nullopt, false, "lamp"},
      // ---- walls
      {"painting", {"picture", "artwork", "art", "poster", "picture frame", "frame", "canvas print"}, P::kWall, {0.4, 0.02, 0.3}, {1.4, 0.06, 1.0}, kCon, false, false, std::nullopt, false, "frame"},
      {"mirror", {"wall mirror", "vanity mirror"}, P::kWall, {0.4, 0.02, 0.5}, {1.0, 0.05, 1.2}, kCon, false, false, std::nullopt, false, "mirror"},
      {"whiteboard", {"white board", "screen", "projection screen", "blackboard"}, P::kWall, {1.2, 0.03, 0.8}, {2.4, 0.06, 1.3}, kCon, false, false, std::nullopt, false, "frame"},
      {"clock", {"wall clock", "cuckoo clock"}, P::kWall, {0.25, 0.04, 0.25}, {0.45, 0.1, 0.6}, kCon, false, false, std::nullopt, false, "clock"},
      // ---- soft furnishings and decor on the floor
      {"rug", {"carpet", "mat", "area rug"}, P::kFloor, {1.2, 0.8, kRugThickness}, {3.0, 2.2, kRugThickness}, kCon, false, false, std::nullopt, false, "rug"},
      {"plant", {"big plant", "indoor plant", "potted plant", "yucca", "ficus", "bamboo", "spathiphyllum", "decorative plant", "orchids"}, P::kFloor, {0.3, 0.3, 0.6}, {0.7, 0.7, 1.8}, kCon, false, false, std::nullopt, false, "plant"},
      {"flower-box", {"planter", "plant box", "window box", "flower pot"}, P::kFloor, {0.5, 0.2, 0.2}, {1.0, 0.35, 0.5}, kConPro, true, false, std::nullopt, true, "planter"},
      {"clothes-horse", {"drying rack", "airer"}, P::kFloor, {0.6, 0.5, 0.9}, {1.4, 0.7, 1.3}, kCon, false, false, std::nullopt, true, "clothes-horse"},
      {"broom", {"mop", "ladder", "step ladder"}, P::kFloor, {0.25, 0.1, 1.2}, {0.5, 0.3, 1.6}, kCon, false, false, std::nullopt, true, "broom"},
      // ---- electronics
      {"tv", {"television", "tv set", "flat screen", "telly"}, P::kSurface, {0.9, 0.06, 0.55}, {1.5, 0.25, 0.9}, kCon, false, false, std::nullopt, false, "screen"},
      {"monitor", {"computer screen", "display", "computer", "imac"}, P::kSurface, {0.45, 0.15, 0.35}, {0.7, 0.25, 0.55}, kCon, false, false, std::nullopt, false, "screen"},
      {"laptop", {"notebook computer", "computer laptop"}, P::kSurface, {0.3, 0.22, 0.02}, {0.4, 0.28, 0.04}, kCon, false, false, std::nullopt, false, "laptop"},
      {"printer", {"copier"}, P::kSurface, {0.35, 0.3, 0.15}, {0.5, 0.45, 0.35}, kCon, false, false, std::nullopt, false, "gadget"},
      {"projector", {"beamer"}, P::kSurface, {0.2, 0.2, 0.07}, {0.35, 0.3, 0.12}, kCon, false, false, std::nullopt, false, "gadget"},
      {"phone", {"telephone", "mobile phone", "wireless phone", "smartphone", "iphone"}, P::kSurface, {0.07, 0.14, 0.01}, {0.2, 0.22, 0.1}, kCon, false, false, std::nullopt, false, "gadget"},
      {"speaker", {"radio", "mp3 station"}, P::kSurface, {0.1, 0.1, 0.15}, {0.3, 0.25, 0.4}, kCon, false, false, std::nullopt, false, "gadget"},
      {"remote", {"remote control"}, P::kSurface, {0.04, 0.15, 0.015}, {0.06, 0.22, 0.03}, kCon, false, false, std::nullopt, false, "gadget"},
      {"alarm-clock", {"alarm clock", "bedside clock"}, P::kSurface, {0.08, 0.05, 0.06}, {0.16, 0.08, 0.12}, kCon, false, false, std::nullopt, false, "clock"},
      // ---- kitchen small things
      {"sink", {"kitchen sink"}, P::kSurface, {0.5, 0.4, 0.2}, {0.9, 0.5, 0.3}, kCon, false, false, std::nullopt, false, "sink"},
      {"microwave", {"microwave oven"}, P::kSurface, {0.45, 0.35, 0.26}, {0.55, 0.42, 0.32}, kCon, false, false, std::nullopt, false, "gadget"},
      {"kettle", {"electric kettle", "espresso kettle", "teapot", "coffee press"}, P::kSurface, {0.15, 0.15, 0.2}, {0.25, 0.22, 0.3}, kCon, false, false, std::nullopt, false, "kettle"},
      {"coffee-machine", {"coffee maker", "coffee brewer", "espresso machine"}, P::kSurface, {0.2, 0.25, 0.3}, {0.35, 0.4, 0.42}, kCon, false, false, std::nullopt, false, "gadget"},
      {"toaster", {"blender", "mixer", "bread box", "kitchen scale"}, P::kSurface, {0.15, 0.15, 0.15}, {0.35, 0.25, 0.4}, kCon, false, false, std::nullopt, false, "gadget"},
      {"knife-stand", {"knife block", "utensils pot", "kitchen tools", "spice tower"}, P::kSurface, {0.1, 0.1, 0.2}, {0.18, 0.15, 0.35}, kCon, false, false, std::nullopt, false, "gadget"},
      {"bottle", {"wine bottle", "oil bottle", "detergent", "detergent bottle", "soap bottle", "shampoo", "flacon", "milk"}, P::kSurface, {0.06, 0.06, 0.18}, {0.12, 0.12, 0.35}, kCon, false, false, std::nullopt, false, "bottle"},
      {"pan", {"frying pan", "pot", "saucepan", "large pan"}, P::kSurface, {0.2, 0.2, 0.06}, {0.45, 0.3, 0.2}, kCon, false, false, std::nullopt, false, "bowl"},
      {"plate", {"dish", "dishes", "oval plate", "place setting"}, P::kSurface, {0.18, 0.18, 0.015}, {0.3, 0.3, 0.03}, kCon, false, false, std::nullopt, false, "plate"},
      {"bowl", {"salad bowl", "soup bowl"}, P::kSurface, {0.12, 0.12, 0.05}, {0.25, 0.25, 0.1}, kCon, false, false, std::nullopt, false, "bowl"},
      {"fruit-bowl", {"fruit basket", "centrepiece", "centerpiece", "bowl with fruits"}, P::kSurface, {0.22, 0.22, 0.08}, {0.35, 0.35, 0.18}, kCon, false, false, std::nullopt, false, "bowl"},
      {"glass", {"drinking glass", "wine glass", "beer glass", "cocktail glass", "tumbler"}, P::kSurface, {0.06, 0.06, 0.1}, {0.09, 0.09, 0.2}, kCon, false, false, std::nullopt, false, "cup"},
      {"cup", {"mug", "coffee cup", "tea cup", "coffee mug", "plastic cup"}, P::kSurface, {0.07, 0.07, 0.08}, {0.12, 0.1, 0.12}, kCon, false, false, std::nullopt, false, "cup"},
      {"candle", {"candles", "candlestick"}, P::kSurface, {0.05, 0.05, 0.1}, {0.1, 0.1, 0.3}, kCon, false, false, std::nullopt, false, "candle"},
      // ---- decor and books
      {"books", {"book", "novels", "stack of books"}, P::kSurface, {0.12, 0.16, 0.18}, {0.5, 0.26, 0.32}, kCon, false, false, std::nullopt, false, "books"},
      {"magazine", {"magazines", "newspaper"}, P::kSurface, {0.2, 0.27, 0.005}, {0.25, 0.32, 0.03}, kCon, false, false, std::nullopt, false, "books"},
      {"vase", {"flower vase", "urn"}, P::kSurface, {0.1, 0.1, 0.2}, {0.25, 0.25, 0.5}, kCon, false, false, std::nullopt, false, "vase"},
      {"small-plant", {"little plant", "succulent", "cactus", "succulent plant", "tulips", "white lily", "spider plant", "houseplant", "bonsai", "bonsai tree", "flowers"}, P::kSurface, {0.1, 0.1, 0.15}, {0.3, 0.3, 0.5}, kCon, false, false, std::nullopt, false, "plant"},
      {"decor", {"ornament", "figurine", "sculpture", "gift", "decoration"}, P::kSurface, {0.08, 0.08, 0.1}, {0.3, 0.2, 0.35}, kCon, false, false, std::nullopt, false, "decor"},
      {"box", {"storage box", "crate", "basket", "bin box"}, P::kSurface, {0.2, 0.15, 0.12}, {0.5, 0.4, 0.35}, kCon, false, false, std::nullopt, false, "box"},
      {"pillow", {"cushion", "pillows", "cushions"}, P::kSurface, {0.4, 0.3, 0.12}, {0.7, 0.5, 0.2}, kCon, false, false, std::nullopt, false, "pillow"},
      {"folded-clothes", {"clothes", "folded clothes", "sweaters", "shirts", "towels", "towel", "linen"}, P::kSurface, {0.25, 0.3, 0.06}, {0.4, 0.4, 0.2}, kCon, false, false, std::nullopt, false, "folded-clothes"},
      {"hanging-clothes", {"suit", "coat", "dress", "jacket"}, P::kSurface, {0.4, 0.1, 0.8}, {0.55, 0.3, 1.1}, kCon, false, false, std::nullopt, false, "hanging-clothes"},
      {"toy", {"toys", "teddy bear", "teddy", "toy train", "puzzle", "doll", "rubik's cube", "xylophone", "wood toy", "rocking horse", "ball"}, P::kSurface, {0.1, 0.1, 0.1}, {0.4, 0.3, 0.35}, kCon, false, false, std::nullopt, false, "toy"},
      {"slippers", {"shoes", "bootie"}, P::kFloor, {0.2, 0.26, 0.05}, {0.3, 0.32, 0.12}, kCon, false, false, std::nullopt, false, "slippers"},
      {"toilet-paper", {"toilet roll", "toilet paper dispenser"}, P::kSurface, {0.1, 0.1, 0.1}, {0.16, 0.14, 0.16}, kCon, false, false, std::nullopt, false, "roll"},
      {"soap", {"soap dispenser", "soap dish"}, P::kSurface, {0.06, 0.06, 0.08}, {0.1, 0.1, 0.2}, kCon, false, false, std::nullopt, false, "dispenser"},
      {"cosmetics", {"cosmetics pot", "lipstick", "perfume", "comb", "toiletries"}, P::kSurface, {0.04, 0.04, 0.05}, {0.12, 0.1, 0.18}, kCon, false, false, std::nullopt, false, "jar"},
      {"stationery", {"pen holder", "pens", "pen box", "stapler", "letter tray", "tray", "ruler", "text marker", "scissors", "calendar"}, P::kSurface, {0.06, 0.06, 0.04}, {0.35, 0.26, 0.15}, kCon, false, false, std::nullopt, false, "gadget"},
      {"tools", {"toolbox", "tool box", "hammer", "drill"}, P::kSurface, {0.2, 0.12, 0.1}, {0.5, 0.25, 0.25}, kCon, false, false, std::nullopt, false, "gadget"},
  };
}

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// "bookshelves" -> "bookshelf"? Plural forms the table does not list are matched by dropping endings.
std::vector<std::string> SingularForms(const std::string& word) {
  std::vector<std::string> out{word};
  auto ends = [&](std::string_view e) { return word.size() > e.size() && word.compare(word.size() - e.size(), e.size(), e) == 0; };
  if (ends("ves")) out.push_back(word.substr(0, word.size() - 3) + "f");
  if (ends("ies")) out.push_back(word.substr(0, word.size() - 3) + "y");
  if (ends("es")) out.push_back(word.substr(0, word.size() - 2));
  if (ends("s")) out.push_back(word.substr(0, word.size() - 1));
  return out;
}

}  // namespace

const std::vector<CategoryInfo>& Categories() {
  static const std::vector<CategoryInfo> table = MakeTable();
  return table;
}

int CategoryTriangleBudget(std::string_view category) {
  const CategoryInfo* info = FindCategory(category);
  if (!info) return 4000;
  const double largest = std::max({info->size_max.x, info->size_max.y, info->size_max.z});
  return largest >= 1.5 ? 8000 : largest >= 0.6 ? 4000 : 1500;
}

const CategoryInfo* FindCategory(std::string_view name) {
  for (const CategoryInfo& c : Categories())
    if (c.name == name) return &c;
  return nullptr;
}

const CategoryInfo* CategoryForWord(std::string_view raw) {
  std::string word = Lower(raw);
  std::replace(word.begin(), word.end(), '_', ' ');
  for (const std::string& form : SingularForms(word)) {
    std::string dashed = form;
    std::replace(dashed.begin(), dashed.end(), ' ', '-');
    if (const CategoryInfo* c = FindCategory(dashed)) return c;
  }
  for (const std::string& form : SingularForms(word))
    for (const CategoryInfo& c : Categories())
      for (std::string_view w : c.words)
        if (w == form) return &c;
  return nullptr;
}

}  // namespace villa
