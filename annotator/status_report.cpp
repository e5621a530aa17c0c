#include "annotator/status_report.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "annotator/packages.h"
#include "util/text_table.h"

namespace villa::annotator {
namespace {

std::string Duration(int seconds) {
  if (seconds < 60) return std::to_string(seconds) + " s";
  if (seconds < 3600) return std::to_string(seconds / 60) + " min " + std::to_string(seconds % 60) + " s";
  return std::to_string(seconds / 3600) + " h " + std::to_string(seconds % 3600 / 60) + " min";
}

std::string KappaText(double kappa) { return std::isnan(kappa) ? "n/a" : FormatFixed(kappa, 2); }

}  // namespace

std::string StatusReport(const Session& session) {
  std::ostringstream out;
  Counts c = session.counts();
  TextTable table({"status", "layouts", "share"});
  table.AddRow({"verified", std::to_string(c.verified), FormatPercent(c.verified, c.total())});
  table.AddRow({"auto", std::to_string(c.automatic), FormatPercent(c.automatic, c.total())});
  table.AddRow({"rejected", std::to_string(c.rejected), FormatPercent(c.rejected, c.total())});
  table.AddRow({"pending", std::to_string(c.pending), FormatPercent(c.pending, c.total())});
  table.AddRow({"total", std::to_string(c.total()), FormatPercent(c.total(), c.total())});
  out << session.dataset().dir.string() << ": " << c.total() - c.pending << " of " << c.total() << " layouts annotated\n"
      << table.Render();

  // Who: layouts acted on, decisions (their last word), time.
  struct Person {
    int layouts = 0, verified = 0, rejected = 0, seconds = 0;
  };
  std::map<std::string, Person> people;
  int unattributed = 0;
  for (int i = 0; i < session.size(); ++i) {
    for (const std::string& who : session.effort(i).annotators) ++people[who].layouts;
    for (const Rating& r : session.Ratings(i)) ++(r.accepted ? people[r.annotator].verified : people[r.annotator].rejected);
    for (const HistoryEntry& h : session.history(i)) {
      if (h.kind == "batch") continue;  // --auto, a split's starting state: nobody's labelling
      if (h.annotator.empty()) {
        ++unattributed;
        continue;
      }
      people[h.annotator].seconds += h.seconds;
    }
  }
  if (!people.empty()) {
    TextTable who({"annotator", "layouts", "verified", "rejected", "time", "per layout"});
    for (const auto& [name, p] : people)
      who.AddRow({name, std::to_string(p.layouts), std::to_string(p.verified), std::to_string(p.rejected), Duration(p.seconds),
                  p.layouts ? Duration(static_cast<int>(std::lround(static_cast<double>(p.seconds) / p.layouts))) : "-"});
    out << "\nwho labelled (journal lines with an annotator; time is time on screen between keys)\n" << who.Render();
  }
  if (unattributed > 0)
    out << unattributed << " journal line" << (unattributed == 1 ? "" : "s")
        << " from before annotator names were kept (journal format 1)\n";

  auto split = ReadSplitRecord(session.dataset().dir);
  Agreement a = session.AgreementFigures();
  if (split || a.all.layouts > 0) {
    out << "\nagreement on layouts decided by two people";
    if (split) {
      int twice = 0;
      for (const std::string& id : split->overlap)
        if (int item = session.dataset().Find(id); item >= 0 && session.Ratings(item).size() >= 2) ++twice;
      out << " (overlap sample of the split: " << split->overlap.size() << " layouts, " << twice << " decided twice so far)";
    }
    out << "\n";
    if (a.all.layouts == 0) {
      out << "none yet: merge the packages (--merge) once two people have labelled the overlap sample\n";
    } else {
      TextTable t({"annotators", "layouts", "accept/reject agree", "kappa", "rooms", "labels agree", "kappa"});
      auto row = [&](const AgreementFigures& f) {
        t.AddRow({f.who, std::to_string(f.layouts),
                  FormatPercent(f.decisions_agreed, f.layouts) + " (" + std::to_string(f.decisions_agreed) + ")",
                  KappaText(f.decision_kappa), std::to_string(f.rooms),
                  f.rooms ? FormatPercent(f.rooms_agreed, f.rooms) + " (" + std::to_string(f.rooms_agreed) + ")" : "-",
                  KappaText(f.label_kappa)});
      };
      for (const AgreementFigures& f : a.pairs) row(f);
      if (a.pairs.size() > 1) row(a.all);
      out << t.Render();
      out << "kappa: Cohen's per pair" << (a.pairs.size() > 1 ? ", Fleiss' over all pairs" : "")
          << "; room labels over the layouts both accepted; n/a when one category was used throughout\n";
      int disagreements = session.CountMatching(Filter::kDisagreements);
      if (disagreements > 0)
        out << disagreements << " layout" << (disagreements == 1 ? "" : "s")
            << " to settle: villa annotate " << session.dataset().dir.string() << " --review\n";
    }
  }
  int next = session.NextToDo(0);
  if (next >= 0)
    out << "next to do: " << session.record(next).id << " (" << session.CountMatching(Filter::kToDo)
        << " to do: pending, or auto and not yet looked at by a person)\n";
  return out.str();
}

}  // namespace villa::annotator
