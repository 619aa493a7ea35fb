#pragma once
// The soft solver's contact graph (docs/soft-solver.md, "Graph colouring"): its pairs grouped into blocks of whole
// islands, and inside a block coloured so that the pairs of one colour share no moving body and four of them can be
// solved at once (SoftSolverWide.cpp). Static and sleeping bodies have no colour (nothing is written to them), so every
// pair on the ground can share one. Pairs that find no colour, and a colour's last pair when it would be alone in
// its batch, are solved one by one after the block's batches. Blocks, colours, batches and lanes are filled in pair
// order, so the solve order is a fixed function of the pairs (deterministic). Storage is kept from step to step.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

class SoftContactGraph {
public:
    /// Colours of the constraint graph: a pair takes the first colour neither of its moving bodies has.
    static constexpr int kColours = 24;
    /// Islands gathered until they hold this many pairs make a block (Build): about 200 KB of rows.
    static constexpr std::size_t kBlockPairs = 256;
    /// Whole islands (moving bodies linked by pairs), in order of their first body, gathered until they hold
    /// kBlockPairs pairs. The solver runs every substep of a block before the next block, so the block's rows and
    /// bodies stay in cache; islands share no moving body, so the order of blocks changes no result. Inside a
    /// block the pairs keep their order: its batches colour by colour, then its overflow one by one.
    struct Block {
        std::size_t bodyBegin = 0, bodyEnd = 0;          // BlockBodies()[bodyBegin, bodyEnd): its moving bodies
        std::size_t batchBegin = 0, batchEnd = 0;        // Batches()[batchBegin, batchEnd)
        std::size_t overflowBegin = 0, overflowEnd = 0;  // Overflow()[overflowBegin, overflowEnd)
    };
    /// Up to four pairs of one colour: lane l is pair[l], or empty (-1).
    struct Batch {
        int colour = 0;
        int pair[4] = {-1, -1, -1, -1};
    };

    /// Builds the blocks, batches and overflow of the pairs whose bodies are ends[i] (indices into `moves`, one
    /// byte per body: non-zero if it moves). Without colouring: one block, every pair one by one in pair order.
    void Build(bool colouring, const std::vector<std::pair<int, int>>& ends, const std::vector<unsigned char>& moves);

    const std::vector<Block>& Blocks() const { return blocks; }
    /// Moving bodies, block by block, in index order.
    const std::vector<int>& BlockBodies() const { return blockBodies; }
    const std::vector<Batch>& Batches() const { return batches; }
    /// Pair indices solved one by one after a block's batches.
    const std::vector<int>& Overflow() const { return overflow; }

private:
    /// Islands by union-find over the pairs of two moving bodies; returns the number of blocks, and leaves in
    /// islandPairs[root] each island's block.
    std::size_t BuildIslands(const std::vector<std::pair<int, int>>& ends, const std::vector<unsigned char>& moves);
    int Root(int i);
    /// Colours the pairs blockPairList[begin, end) and appends their batches and overflow.
    void Colour(std::size_t begin, std::size_t end, const std::vector<std::pair<int, int>>& ends,
                const std::vector<unsigned char>& moves);

    // The inputs of the last Build (its result is kept while they stay the same).
    bool built = false, builtColouring = false;
    std::vector<std::pair<int, int>> builtEnds;
    std::vector<unsigned char> builtMoves;

    std::vector<Block> blocks;
    std::vector<int> blockBodies;
    std::vector<Batch> batches;
    std::vector<int> overflow;
    std::vector<int> islandParent;           // per body: union-find parent over the pairs
    std::vector<int> islandPairs;            // per island root: its pair count, then its block
    std::vector<std::size_t> blockStart;     // per block: where its bodies (then its pairs) start
    std::vector<int> blockPairList;          // pair indices, block by block, in pair order
    std::vector<std::uint32_t> bodyColours;  // per body: the colours it has this step (bit c)
    std::vector<int> colourPairs[kColours];  // pair indices of each colour, in pair order
};
