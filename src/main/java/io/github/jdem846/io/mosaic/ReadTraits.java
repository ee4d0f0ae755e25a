package io.github.jdem846.io.mosaic;

import io.github.jdem846.io.source.RasterSource;

/**
 * How a file's reader likes to be read ({@link RasterSource#naturalRowBlock()}, {@link RasterSource#blockBytes()},
 * {@link RasterSource#bandCells()}, {@link RasterSource#readsRowsIndependently()}), kept from its header so that
 * the mosaic can plan reads without keeping the file open.
 */
record ReadTraits(int rowBlock, long blockBytes, long bandCells, boolean independent) {

    static ReadTraits of(RasterSource source) {
        return new ReadTraits(Math.max(1, source.naturalRowBlock()), Math.max(0, source.blockBytes()),
                source.bandCells(), source.readsRowsIndependently());
    }
}
