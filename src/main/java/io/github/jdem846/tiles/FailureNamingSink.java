package io.github.jdem846.tiles;

import io.github.jdem846.internal.IoMessages;
import java.io.IOException;
import java.nio.file.Path;

/**
 * A sink whose failures name the output the user gave, with the file system's reason ("cannot write
 * relief.pmtiles: No space left on device"), not a hidden staging file or an exception's class name.
 */
final class FailureNamingSink implements TileSink {

    private final TileSink sink;
    private final Path output;

    FailureNamingSink(TileSink sink, Path output) {
        this.sink = sink;
        this.output = output;
    }

    @Override
    public void write(WebMercatorTile tile, byte[] png) throws IOException {
        try {
            sink.write(tile, png);
        } catch (IOException e) {
            throw IoMessages.naming(e, output);
        }
    }

    @Override
    public void commit(TileSetInfo info) throws IOException {
        try {
            sink.commit(info);
        } catch (IOException e) {
            throw IoMessages.naming(e, output);
        }
    }

    @Override
    public void close() throws IOException {
        try {
            sink.close();
        } catch (IOException e) {
            throw IoMessages.naming(e, output);
        }
    }
}
