package io.github.jdem846.output;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;

/** Positional writes that write everything ({@link FileChannel#write(ByteBuffer, long)} may write less). */
final class FileChannels {

    private FileChannels() {
    }

    /** Writes all of {@code data} at {@code position}. */
    static void writeFully(FileChannel channel, ByteBuffer data, long position) throws IOException {
        for (long at = position; data.hasRemaining(); ) {
            at += channel.write(data, at);
        }
    }
}
