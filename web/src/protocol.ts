// The wire protocol between `pendulab serve` and the page (docs/web.md), with no DOM: types of the JSON
// commands and notices, and the decoding of binary state frames.
//
// One module per part (protocol/): frames.ts (the binary state frames: the layout of
// python/pendulab/server/frame.json, which it imports; decodeFrames, encodeFrames, ProtocolError),
// messages.ts (the JSON commands, page → server, and notices, server → page: status, error, event;
// parseNotice), rest.ts (the answers of /api/schema, /api/scenarios, /api/exact, /api/reduced,
// /api/em_map). This file re-exports them all, so the page imports the protocol from one place.
export * from './protocol/frames';
export * from './protocol/messages';
export * from './protocol/rest';
