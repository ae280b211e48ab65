#include "planner/graph/dv_graph.hpp"

#include <algorithm>
#include <cmath>

namespace ifar::graph {
namespace {

const std::vector<VisibilityLink> kNoLinks;

}  // namespace

VertexId DvGraph::addVertex(const Vertex& vertex)
{
  Vertex stored = vertex;
  stored.id = static_cast<VertexId>(vertices_.size());
  stored.alive = true;
  vertices_.push_back(stored);
  links_.emplace_back();
  ++live_vertices_;
  return stored.id;
}

bool DvGraph::removeVertex(VertexId id)
{
  if (!contains(id)) {
    return false;
  }
  for (const auto& link : links_[id]) {
    auto& other = links_[link.other];
    other.erase(std::remove_if(other.begin(), other.end(),
                               [id](const VisibilityLink& entry) { return entry.other == id; }),
                other.end());
    --visibility_edges_;
  }
  links_[id].clear();
  links_[id].shrink_to_fit();
  for (auto& edge : interaction_edges_) {
    if (edge.from == id || edge.to == id) {
      edge.alive = false;
    }
  }
  vertices_[id].alive = false;
  --live_vertices_;
  return true;
}

bool DvGraph::moveVertex(VertexId id, const geometry::Point& position)
{
  if (!contains(id) || !position.allFinite()) {
    return false;
  }
  vertices_[id].position = position;
  for (auto& link : links_[id]) {
    link.length = (vertices_[link.other].position - position).norm();
    for (auto& back : links_[link.other]) {
      if (back.other == id) {
        back.length = link.length;
      }
    }
  }
  return true;
}

bool DvGraph::updateVertexGeometry(VertexId id, const geometry::Point& position,
                                   const geometry::Point& previous, const geometry::Point& next)
{
  if (!contains(id) || !previous.allFinite() || !next.allFinite() || !moveVertex(id, position)) {
    return false;
  }
  vertices_[id].previous = previous;
  vertices_[id].next = next;
  return true;
}

bool DvGraph::setUnseenVotes(VertexId id, int votes)
{
  if (!contains(id)) {
    return false;
  }
  vertices_[id].unseen_votes = votes;
  return true;
}

EdgeStatus DvGraph::addVisibilityEdge(VertexId a, VertexId b)
{
  if (a == b || !contains(a) || !contains(b)) {
    return EdgeStatus::Rejected;
  }
  if (hasVisibilityEdge(a, b)) {
    return EdgeStatus::AlreadyPresent;
  }
  const double length = (vertices_[a].position - vertices_[b].position).norm();
  links_[a].push_back(VisibilityLink{b, length});
  links_[b].push_back(VisibilityLink{a, length});
  ++visibility_edges_;
  return EdgeStatus::Added;
}

bool DvGraph::removeVisibilityEdge(VertexId a, VertexId b)
{
  if (!hasVisibilityEdge(a, b)) {
    return false;
  }
  const auto erase = [](std::vector<VisibilityLink>& links, VertexId other) {
    links.erase(std::remove_if(links.begin(), links.end(),
                               [other](const VisibilityLink& entry) { return entry.other == other; }),
                links.end());
  };
  erase(links_[a], b);
  erase(links_[b], a);
  --visibility_edges_;
  return true;
}

bool DvGraph::hasVisibilityEdge(VertexId a, VertexId b) const
{
  if (!contains(a) || !contains(b)) {
    return false;
  }
  // Scan the shorter list.
  const bool a_shorter = links_[a].size() <= links_[b].size();
  const auto& links = a_shorter ? links_[a] : links_[b];
  const VertexId other = a_shorter ? b : a;
  return std::any_of(links.begin(), links.end(),
                     [other](const VisibilityLink& link) { return link.other == other; });
}

const std::vector<VisibilityLink>& DvGraph::visibilityLinks(VertexId id) const
{
  return contains(id) ? links_[id] : kNoLinks;
}

std::optional<std::uint32_t> DvGraph::addInteractionEdge(const InteractionEdge& edge)
{
  if (!contains(edge.from) || !contains(edge.to) || edge.from == edge.to || !std::isfinite(edge.cost) ||
      edge.cost < 0.0) {
    return std::nullopt;
  }
  InteractionEdge stored = edge;
  stored.alive = true;
  interaction_edges_.push_back(stored);
  return static_cast<std::uint32_t>(interaction_edges_.size() - 1);
}

bool DvGraph::setInteractionCost(std::uint32_t index, double cost)
{
  if (index >= interaction_edges_.size() || !interaction_edges_[index].alive || !std::isfinite(cost) ||
      cost < 0.0) {
    return false;
  }
  interaction_edges_[index].cost = cost;
  return true;
}

std::size_t DvGraph::removeInteractionEdges(std::int64_t object_id)
{
  std::size_t removed = 0;
  for (auto& edge : interaction_edges_) {
    if (edge.alive && edge.object_id == object_id) {
      edge.alive = false;
      ++removed;
    }
  }
  return removed;
}

std::size_t DvGraph::interactionEdgeCount() const
{
  return static_cast<std::size_t>(std::count_if(interaction_edges_.begin(), interaction_edges_.end(),
                                                [](const InteractionEdge& edge) { return edge.alive; }));
}

void DvGraph::shrinkToFit()
{
  vertices_.shrink_to_fit();
  links_.shrink_to_fit();
  for (auto& links : links_) {
    links.shrink_to_fit();
  }
  interaction_edges_.shrink_to_fit();
}

std::size_t DvGraph::memoryBytes() const
{
  std::size_t bytes = vertices_.capacity() * sizeof(Vertex) +
                      links_.capacity() * sizeof(std::vector<VisibilityLink>) +
                      interaction_edges_.capacity() * sizeof(InteractionEdge);
  for (const auto& links : links_) {
    bytes += links.capacity() * sizeof(VisibilityLink);
  }
  return bytes;
}

}  // namespace ifar::graph
