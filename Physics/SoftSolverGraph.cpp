// The soft solver's contact graph: blocks of whole islands, and colours inside a block (SoftSolverGraph.h).
#include "Physics/SoftSolverGraph.h"

#include <algorithm>

namespace {

using Ends = std::vector<std::pair<int, int>>;
using Moves = std::vector<unsigned char>;

/// A pair's moving body (a if it moves, else b): the one that places the pair in an island.
inline int MovingBody(const std::pair<int, int>& ends, const Moves& moves) {
    return moves[static_cast<std::size_t>(ends.first)] != 0 ? ends.first : ends.second;
}

}  // namespace

void SoftContactGraph::Build(bool colouring, const Ends& ends, const Moves& moves) {
    // The graph is a function of its inputs alone: a resting world, whose pairs and moving bodies are last step's,
    // keeps last step's graph (1.5 % of a 10-box tower's step, callgrind). Capacities are kept from step to
    // step, so the steady state allocates nothing.
    if (built && colouring == builtColouring && ends == builtEnds && moves == builtMoves) return;
    built = true;
    builtColouring = colouring;
    builtEnds = ends;
    builtMoves = moves;
    const std::size_t n = moves.size();
    blocks.clear();
    blockBodies.clear();
    batches.clear();
    overflow.clear();
    if (!colouring || ends.size() < kBlockPairs) {
        // One block of every moving body: without colouring, every pair one by one in pair order; with fewer pairs
        // than a block holds (what the islands below would give: one block, bodies and pairs in order), the
        // batches and overflow of all of them. A small world pays for no islands.
        for (std::size_t i = 0; i < n; ++i)
            if (moves[i] != 0) blockBodies.push_back(static_cast<int>(i));
        if (colouring) {
            blockPairList.resize(ends.size());
            for (std::size_t i = 0; i < ends.size(); ++i) blockPairList[i] = static_cast<int>(i);
            bodyColours.assign(n, 0u);
            Colour(0, ends.size(), ends, moves);
        } else {
            for (std::size_t i = 0; i < ends.size(); ++i) overflow.push_back(static_cast<int>(i));
        }
        blocks.push_back({0, blockBodies.size(), 0, batches.size(), 0, overflow.size()});
        return;
    }
    const std::size_t blockCount = BuildIslands(ends, moves);
    auto blockOf = [&](int body) {
        return static_cast<std::size_t>(islandPairs[static_cast<std::size_t>(Root(body))]);
    };
    // Bodies and pairs by block, each in its own order (counting sort).
    blockStart.assign(blockCount + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (moves[i] != 0) ++blockStart[blockOf(static_cast<int>(i)) + 1];
    for (std::size_t b = 0; b < blockCount; ++b) blockStart[b + 1] += blockStart[b];
    blocks.resize(blockCount);
    for (std::size_t b = 0; b < blockCount; ++b) blocks[b].bodyBegin = blocks[b].bodyEnd = blockStart[b];
    blockBodies.resize(blockStart[blockCount]);
    for (std::size_t i = 0; i < n; ++i)
        if (moves[i] != 0) blockBodies[blocks[blockOf(static_cast<int>(i))].bodyEnd++] = static_cast<int>(i);
    blockStart.assign(blockCount + 1, 0);
    for (const std::pair<int, int>& pair : ends) ++blockStart[blockOf(MovingBody(pair, moves)) + 1];
    for (std::size_t b = 0; b < blockCount; ++b) blockStart[b + 1] += blockStart[b];
    blockPairList.resize(ends.size());
    for (std::size_t i = 0; i < ends.size(); ++i)
        blockPairList[blockStart[blockOf(MovingBody(ends[i], moves))]++] = static_cast<int>(i);
    // blockStart[b] is now where block b + 1's pairs start.
    bodyColours.assign(n, 0u);
    for (std::size_t b = 0; b < blockCount; ++b) {
        Block& block = blocks[b];
        block.batchBegin = batches.size();
        block.overflowBegin = overflow.size();
        Colour(b == 0 ? 0 : blockStart[b - 1], blockStart[b], ends, moves);
        block.batchEnd = batches.size();
        block.overflowEnd = overflow.size();
    }
}

int SoftContactGraph::Root(int i) {
    while (islandParent[static_cast<std::size_t>(i)] != i) {
        int& parent = islandParent[static_cast<std::size_t>(i)];
        parent = islandParent[static_cast<std::size_t>(parent)];  // path halving
        i = parent;
    }
    return i;
}

std::size_t SoftContactGraph::BuildIslands(const Ends& ends, const Moves& moves) {
    // Union-find over the pairs of two moving bodies, the smaller root kept (a fixed function of the pairs).
    const std::size_t n = moves.size();
    islandParent.resize(n);
    for (std::size_t i = 0; i < n; ++i) islandParent[i] = static_cast<int>(i);
    for (const std::pair<int, int>& pair : ends) {
        if (moves[static_cast<std::size_t>(pair.first)] == 0 || moves[static_cast<std::size_t>(pair.second)] == 0)
            continue;
        const int ra = Root(pair.first), rb = Root(pair.second);
        if (ra != rb) islandParent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
    // Pairs per island, then islands into blocks in order of their first body, closed at kBlockPairs pairs.
    islandPairs.assign(n, 0);
    for (const std::pair<int, int>& pair : ends) ++islandPairs[static_cast<std::size_t>(Root(MovingBody(pair, moves)))];
    std::size_t blockCount = 0, open = 0;  // blocks closed; pairs in the open block
    bool openUsed = false;
    for (std::size_t i = 0; i < n; ++i) {
        if (moves[i] == 0) continue;
        const std::size_t r = static_cast<std::size_t>(Root(static_cast<int>(i)));
        if (r != i) continue;  // the root is the island's first body: each island is met once, in order
        open += static_cast<std::size_t>(islandPairs[r]);
        islandPairs[r] = static_cast<int>(blockCount);  // read once: from here it holds the island's block
        openUsed = true;
        if (open >= kBlockPairs) {
            ++blockCount;
            open = 0;
            openUsed = false;
        }
    }
    if (openUsed) ++blockCount;
    return blockCount;
}

void SoftContactGraph::Colour(std::size_t begin, std::size_t end, const Ends& ends, const Moves& moves) {
    // Colour the pairs: the first colour free at both moving bodies.
    for (std::vector<int>& colour : colourPairs) colour.clear();
    for (std::size_t at = begin; at < end; ++at) {
        const int i = blockPairList[at];
        const std::pair<int, int>& pair = ends[static_cast<std::size_t>(i)];
        const std::size_t a = static_cast<std::size_t>(pair.first), b = static_cast<std::size_t>(pair.second);
        const bool movesA = moves[a] != 0, movesB = moves[b] != 0;
        const std::uint32_t taken = (movesA ? bodyColours[a] : 0u) | (movesB ? bodyColours[b] : 0u);
        int colour = 0;
        while (colour < kColours && (taken >> colour & 1u) != 0u) ++colour;
        if (colour == kColours || (!movesA && !movesB)) {
            overflow.push_back(i);
            continue;
        }
        if (movesA) bodyColours[a] |= 1u << colour;
        if (movesB) bodyColours[b] |= 1u << colour;
        colourPairs[colour].push_back(i);
    }
    // Four pairs of a colour per batch; a lane without a pair stays empty (-1).
    for (int colour = 0; colour < kColours; ++colour) {
        const std::vector<int>& list = colourPairs[colour];
        for (std::size_t first = 0; first < list.size(); first += 4) {
            // A batch of one pair would do four lanes' work for one: that pair is solved one by one, with the
            // overflow (a column of 10 cubes has two colours of five pairs: 18 % less time in the lab tool).
            if (list.size() - first == 1) {
                overflow.push_back(list[first]);
                continue;
            }
            batches.emplace_back();
            Batch& batch = batches.back();
            batch.colour = colour;
            for (std::size_t lane = 0; lane < 4 && first + lane < list.size(); ++lane)
                batch.pair[lane] = list[first + lane];
        }
    }
}
