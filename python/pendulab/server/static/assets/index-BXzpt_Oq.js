(function(){const t=document.createElement("link").relList;if(t&&t.supports&&t.supports("modulepreload"))return;for(const s of document.querySelectorAll('link[rel="modulepreload"]'))i(s);new MutationObserver(s=>{for(const r of s)if(r.type==="childList")for(const a of r.addedNodes)a.tagName==="LINK"&&a.rel==="modulepreload"&&i(a)}).observe(document,{childList:!0,subtree:!0});function e(s){const r={};return s.integrity&&(r.integrity=s.integrity),s.referrerPolicy&&(r.referrerPolicy=s.referrerPolicy),s.crossOrigin==="use-credentials"?r.credentials="include":s.crossOrigin==="anonymous"?r.credentials="omit":r.credentials="same-origin",r}function i(s){if(s.ep)return;s.ep=!0;const r=e(s);fetch(s.href,r)}})();const Mm=["t","x1","x2","x3","v1","v2","v3","energy","j3","tension","power","a1","a2","a3","pivot1","pivot2","pivot3","taut"],ym={fields:Mm},ch=ym.fields,Em=ch.length,Na=8*Em;function yn(n){const t=ch.indexOf(n);if(t<0)throw new Error(`frame.json lacks the field ${n}`);return t}const Di={t:yn("t"),x:[yn("x1"),yn("x2"),yn("x3")],v:[yn("v1"),yn("v2"),yn("v3")],energy:yn("energy"),j3:yn("j3"),tension:yn("tension"),power:yn("power"),a:[yn("a1"),yn("a2"),yn("a3")],pivot:[yn("pivot1"),yn("pivot2"),yn("pivot3")],taut:yn("taut")};class li extends Error{}function bm(n){if(n.byteLength===0||n.byteLength%Na!==0)throw new li(`a frame message has a multiple of ${Na} bytes, got ${n.byteLength}`);const t=new DataView(n),e=n.byteLength/Na,i=[];for(let s=0;s<e;s++){const r=s*Na,a=c=>t.getFloat64(r+8*c,!0),o=c=>[a(c[0]),a(c[1]),a(c[2])];i.push({t:a(Di.t),x:o(Di.x),v:o(Di.v),energy:a(Di.energy),j3:a(Di.j3),tension:a(Di.tension),power:a(Di.power),a:o(Di.a),pivot:o(Di.pivot),taut:a(Di.taut)!==0})}return i}function cu(n){return typeof n=="object"&&n!==null&&!Array.isArray(n)}function wm(n){let t;try{t=JSON.parse(n)}catch(e){throw new li(`notice is not JSON: ${String(e)}`)}if(!cu(t))throw new li("notice is not a JSON object");if(t.type==="error"&&typeof t.message=="string"){const e=typeof t.command=="string"?t.command:null;return{type:"error",message:t.message,command:e}}if(t.type==="status"){const e=t.params;if(!cu(e)||typeof t.epoch!="number"||typeof t.method!="string")throw new li("status notice lacks epoch, method or params");const i=t.frame_fields;if(Array.isArray(i)&&i.join(",")!==ch.join(","))throw new li(`server frame layout ${i.join(",")} differs from the page's`);return t}if(t.type==="event")return Tm(t);throw new li(`unknown notice type ${JSON.stringify(t.type)}`)}function al(n){return typeof n=="number"&&Number.isFinite(n)}function Tm(n){const{kind:t,t:e,energy_lost:i,x:s,epoch:r}=n,a=n.skipped??0;if(t!=="slack"&&t!=="taut")throw new li(`event notice: kind ${JSON.stringify(t)} is not "slack" or "taut"`);if(!al(e))throw new li("event notice: t is not a finite number");if(!al(i)||i<0)throw new li("event notice: energy_lost is not a finite number ≥ 0");if(!Array.isArray(s)||s.length!==3||!s.every(al))throw new li("event notice: x is not 3 finite numbers");if(!Number.isInteger(r)||!Number.isInteger(a)||a<0)throw new li("event notice: epoch or skipped is not an integer");return{type:"event",kind:t,t:e,energy_lost:i,x:[s[0],s[1],s[2]],epoch:r,skipped:a}}function Am(n){const t=n.protocol==="https:"?"wss:":"ws:",e=n.pathname.endsWith("/")?n.pathname:n.pathname.replace(/[^/]*$/,"");return`${t}//${n.host}${e}ws`}class Rm{constructor(t,e){this.url=t,this.handlers=e,this.open()}url;handlers;ws=null;retryMs=500;closedByUs=!1;open(){const t=new WebSocket(this.url);t.binaryType="arraybuffer",t.onopen=()=>{this.retryMs=500,this.handlers.onOpen()},t.onmessage=e=>{try{e.data instanceof ArrayBuffer?this.handlers.onFrames(bm(e.data)):typeof e.data=="string"&&this.handlers.onNotice(wm(e.data))}catch(i){if(i instanceof li)this.handlers.onProtocolError(i.message);else throw i}},t.onclose=()=>{this.ws=null,this.handlers.onClose(),this.closedByUs||(setTimeout(()=>this.open(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))},this.ws=t}get isOpen(){return this.ws!==null&&this.ws.readyState===WebSocket.OPEN}send(t){return!this.isOpen||this.ws===null?!1:(this.ws.send(JSON.stringify(t)),!0)}close(){this.closedByUs=!0,this.ws?.close()}}const Cm=["spring","string"];function Pm(n){return!Cm.includes(n??"ideal")}function hh(n){return n==="spring"?"the swinging spring leaves the sphere (its length varies): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown":n==="string"?"the string goes slack (free flight inside the sphere): V_eff, the energy–momentum map, the reduced view and the exact solution belong to the rod pendulum and are not shown":null}function yf(n,t){return n==="spring"?"coil":n==="string"?t?"taut string":"slack string":"rod"}function Pe(n,t=6){if(n==null||Number.isNaN(n))return"—";if(!Number.isFinite(n))return n>0?"∞":"−∞";if(n===0)return"0";const e=Math.abs(n);return e>=.001&&e<1e6?n.toPrecision(t):n.toExponential(t-1)}const Lm=5;function Dm(n){const t=n.kind==="slack"?"the string went slack (tension 0: free flight)":`the string snapped taut, lost ${Pe(n.energy_lost,3)} J`,e=n.skipped>0?` (${n.skipped} earlier event${n.skipped>1?"s":""} of this moment not shown)`:"";return`t = ${n.t.toFixed(3)} s: ${t}${e}`}function Nm(n){return n.kind==="slack"?["went slack",`t = ${Pe(n.t,6)} s`,""]:["snapped taut",`t = ${Pe(n.t,6)} s, lost ${Pe(n.energy_lost,4)}`,"J"]}function Im(n,t,e,i=Lm){if(e===null||t.epoch!==e)return n;const s=[...n,t];return s.length>i?s.slice(s.length-i):s}function Um(n,t){const e=t.reference,i=t.status,s=t.tensionExtremes,r=[["t",Pe(n?.t,7),"s"],["E",Pe(n?.energy,10),"J"],["E − E₀",n&&e?Pe(n.energy-e.energy,3):"—","J"],["J₃",Pe(n?.j3,10),"kg m²/s"],["J₃ − J₃(0)",n&&e?Pe(n.j3-e.j3,3):"—","kg m²/s"],["tension",Pe(n?.tension,6),"N"],["tension min",s?`${Pe(s.min,6)} (t = ${Pe(s.tMin,4)} s)`:"—","N"],["tension max",s?`${Pe(s.max,6)} (t = ${Pe(s.tMax,4)} s)`:"—","N"],["z",Pe(n?.x[2],6),"m"],["method",i?`${i.method}${i.adaptive?"":`, dt = ${i.dt} s`}`:"—",""],["state",i?`${i.paused?"paused":"running"}${i.lagging?" (lagging: slower than asked)":""}`:"—",""]];i&&i.model!=="ideal"&&(r.splice(1,0,["model",i.model,""]),r.splice(4,0,["power P = dE/dt",Pe(n?.power,6),"W"]));const a=r.findIndex(c=>c[0]==="tension"),o=yf(i?.model,n?.taut??!0);if(o==="coil"&&i){const c=n?Math.hypot(...n.x):null;r[a]=["spring force k(|r| − l₀)",Pe(n?.tension,6),"N"],r.splice(a+1,0,["spring length |r|",Pe(c,6),"m"],["stretch |r| − l₀",c===null?"—":Pe(c-i.params.length,4),"m"])}else o==="slack string"?(r[a]=["tension","slack (0)","N"],r.splice(a+1,0,["string",`slack: free flight, |x| = ${Pe(n?Math.hypot(...n.x):null,5)} m`,""])):o==="taut string"&&r.splice(a+1,0,["string","taut",""]);if(i?.model==="string"){const c=[...t.events].reverse().map(Nm);r.push(...c.length>0?c:[["events","none yet (slack, snaps)",""]])}return r}function Fm(n){const t=n.status,e=hh(t?.model);return e!==null?e:t&&t.model!=="ideal"?`the exact solution exists for the ideal pendulum only; this is the ${t.model} model`:n.exactError??n.exact?.phases_note??""}function Om(n){if(n===null)return[];const t=n.turning_heights,e=[["kind",n.kind,""],["z₁, z₂",`${Pe(t[0])}, ${Pe(t[1])}`,"m"]];return t.length>2&&e.push(["z₃ (outside)",Pe(t[2]),"m"]),e.push(["T_z",n.period_z_infinite?"∞":Pe(n.period_z),"s"]),n.azimuth_advance!==null&&e.push(["Δφ per T_z",Pe(n.azimuth_advance),"rad"]),n.rotation_number!==null&&e.push(["W = Δφ/2π",Pe(n.rotation_number),""]),n.phases!==null&&(e.push(["Δφ dynamic",Pe(n.phases.dynamic),"rad"]),e.push(["Δφ geometric",Pe(n.phases.geometric),"rad"])),e}class Bm{live;exactTable;note;constructor(t){const e=i=>{const s=document.createElement("h3");s.textContent=i,t.appendChild(s)};e("Now (from the server)"),this.live=document.createElement("table"),t.appendChild(this.live),e("Exact solution of this orbit"),this.exactTable=document.createElement("table"),t.appendChild(this.exactTable),this.note=document.createElement("p"),this.note.className="note",t.appendChild(this.note)}fill(t,e){for(;t.rows.length>e.length;)t.deleteRow(-1);e.forEach(([i,s,r],a)=>{const o=t.rows[a]??t.insertRow();for(;o.cells.length<3;)o.insertCell();const[c,l,h]=[o.cells[0],o.cells[1],o.cells[2]];c&&c.textContent!==i&&(c.textContent=i),l&&l.textContent!==s&&(l.textContent=s),h&&h.textContent!==r&&(h.textContent=r)})}update(t,e){this.fill(this.live,Um(t,e)),this.fill(this.exactTable,Om(e.exact));const i=Fm(e);this.note.textContent!==i&&(this.note.textContent=i)}}class zi{constructor(t,e,i,s,r="div"){this.parent=t,this.object=e,this.property=i,this._disabled=!1,this._hidden=!1,this.initialValue=this.getValue(),this.domElement=document.createElement(r),this.domElement.classList.add("lil-controller"),this.domElement.classList.add(s),this.$name=document.createElement("div"),this.$name.classList.add("lil-name"),zi.nextNameID=zi.nextNameID||0,this.$name.id=`lil-gui-name-${++zi.nextNameID}`,this.$widget=document.createElement("div"),this.$widget.classList.add("lil-widget"),this.$disable=this.$widget,this.domElement.appendChild(this.$name),this.domElement.appendChild(this.$widget),this.domElement.addEventListener("keydown",a=>a.stopPropagation()),this.domElement.addEventListener("keyup",a=>a.stopPropagation()),this.parent.children.push(this),this.parent.controllers.push(this),this.parent.$children.appendChild(this.domElement),this._listenCallback=this._listenCallback.bind(this),this.name(i)}name(t){return this._name=t,this.$name.textContent=t,this}onChange(t){return this._onChange=t,this}_callOnChange(){this.parent._callOnChange(this),this._onChange!==void 0&&this._onChange.call(this,this.getValue()),this._changed=!0}onFinishChange(t){return this._onFinishChange=t,this}_callOnFinishChange(){this._changed&&(this.parent._callOnFinishChange(this),this._onFinishChange!==void 0&&this._onFinishChange.call(this,this.getValue())),this._changed=!1}reset(){return this.setValue(this.initialValue),this._callOnFinishChange(),this}enable(t=!0){return this.disable(!t)}disable(t=!0){return t===this._disabled?this:(this._disabled=t,this.domElement.classList.toggle("lil-disabled",t),this.$disable.toggleAttribute("disabled",t),this)}show(t=!0){return this._hidden=!t,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}options(t){const e=this.parent.add(this.object,this.property,t);return e.name(this._name),this.destroy(),e}min(t){return this}max(t){return this}step(t){return this}decimals(t){return this}listen(t=!0){return this._listening=t,this._listenCallbackID!==void 0&&(cancelAnimationFrame(this._listenCallbackID),this._listenCallbackID=void 0),this._listening&&this._listenCallback(),this}_listenCallback(){this._listenCallbackID=requestAnimationFrame(this._listenCallback);const t=this.save();t!==this._listenPrevValue&&this.updateDisplay(),this._listenPrevValue=t}getValue(){return this.object[this.property]}setValue(t){return this.getValue()!==t&&(this.object[this.property]=t,this._callOnChange(),this.updateDisplay()),this}updateDisplay(){return this}load(t){return this.setValue(t),this._callOnFinishChange(),this}save(){return this.getValue()}destroy(){this.listen(!1),this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.controllers.splice(this.parent.controllers.indexOf(this),1),this.parent.$children.removeChild(this.domElement)}}class zm extends zi{constructor(t,e,i){super(t,e,i,"lil-boolean","label"),this.$input=document.createElement("input"),this.$input.setAttribute("type","checkbox"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$widget.appendChild(this.$input),this.$input.addEventListener("change",()=>{this.setValue(this.$input.checked),this._callOnFinishChange()}),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.checked=this.getValue(),this}}function ac(n){let t,e;return(t=n.match(/(#|0x)?([a-f0-9]{6})/i))?e=t[2]:(t=n.match(/rgb\(\s*(\d*)\s*,\s*(\d*)\s*,\s*(\d*)\s*\)/))?e=parseInt(t[1]).toString(16).padStart(2,0)+parseInt(t[2]).toString(16).padStart(2,0)+parseInt(t[3]).toString(16).padStart(2,0):(t=n.match(/^#?([a-f0-9])([a-f0-9])([a-f0-9])$/i))&&(e=t[1]+t[1]+t[2]+t[2]+t[3]+t[3]),e?"#"+e:!1}const km={isPrimitive:!0,match:n=>typeof n=="string",fromHexString:ac,toHexString:ac},ma={isPrimitive:!0,match:n=>typeof n=="number",fromHexString:n=>parseInt(n.substring(1),16),toHexString:n=>"#"+n.toString(16).padStart(6,0)},Hm={isPrimitive:!1,match:n=>Array.isArray(n)||ArrayBuffer.isView(n),fromHexString(n,t,e=1){const i=ma.fromHexString(n);t[0]=(i>>16&255)/255*e,t[1]=(i>>8&255)/255*e,t[2]=(i&255)/255*e},toHexString([n,t,e],i=1){i=255/i;const s=n*i<<16^t*i<<8^e*i<<0;return ma.toHexString(s)}},Gm={isPrimitive:!1,match:n=>Object(n)===n,fromHexString(n,t,e=1){const i=ma.fromHexString(n);t.r=(i>>16&255)/255*e,t.g=(i>>8&255)/255*e,t.b=(i&255)/255*e},toHexString({r:n,g:t,b:e},i=1){i=255/i;const s=n*i<<16^t*i<<8^e*i<<0;return ma.toHexString(s)}},Vm=[km,ma,Hm,Gm];function Wm(n){return Vm.find(t=>t.match(n))}class Xm extends zi{constructor(t,e,i,s){super(t,e,i,"lil-color"),this.$input=document.createElement("input"),this.$input.setAttribute("type","color"),this.$input.setAttribute("tabindex",-1),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$text=document.createElement("input"),this.$text.setAttribute("type","text"),this.$text.setAttribute("spellcheck","false"),this.$text.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$display.appendChild(this.$input),this.$widget.appendChild(this.$display),this.$widget.appendChild(this.$text),this._format=Wm(this.initialValue),this._rgbScale=s,this._initialValueHexString=this.save(),this._textFocused=!1,this.$input.addEventListener("input",()=>{this._setValueFromHexString(this.$input.value)}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$text.addEventListener("input",()=>{const r=ac(this.$text.value);r&&this._setValueFromHexString(r)}),this.$text.addEventListener("focus",()=>{this._textFocused=!0,this.$text.select()}),this.$text.addEventListener("blur",()=>{this._textFocused=!1,this.updateDisplay(),this._callOnFinishChange()}),this.$disable=this.$text,this.updateDisplay()}reset(){return this._setValueFromHexString(this._initialValueHexString),this}_setValueFromHexString(t){if(this._format.isPrimitive){const e=this._format.fromHexString(t);this.setValue(e)}else this._format.fromHexString(t,this.getValue(),this._rgbScale),this._callOnChange(),this.updateDisplay()}save(){return this._format.toHexString(this.getValue(),this._rgbScale)}load(t){return this._setValueFromHexString(t),this._callOnFinishChange(),this}updateDisplay(){return this.$input.value=this._format.toHexString(this.getValue(),this._rgbScale),this._textFocused||(this.$text.value=this.$input.value.substring(1)),this.$display.style.backgroundColor=this.$input.value,this}}class ol extends zi{constructor(t,e,i){super(t,e,i,"lil-function"),this.$button=document.createElement("button"),this.$button.appendChild(this.$name),this.$widget.appendChild(this.$button),this.$button.addEventListener("click",s=>{s.preventDefault(),this.getValue().call(this.object),this._callOnChange()}),this.$button.addEventListener("touchstart",()=>{},{passive:!0}),this.$disable=this.$button}}class $m extends zi{constructor(t,e,i,s,r,a){super(t,e,i,"lil-number"),this._initInput(),this.min(s),this.max(r);const o=a!==void 0;this.step(o?a:this._getImplicitStep(),o),this.updateDisplay()}decimals(t){return this._decimals=t,this.updateDisplay(),this}min(t){return this._min=t,this._onUpdateMinMax(),this}max(t){return this._max=t,this._onUpdateMinMax(),this}step(t,e=!0){return this._step=t,this._stepExplicit=e,this}updateDisplay(){const t=this.getValue();if(this._hasSlider){let e=(t-this._min)/(this._max-this._min);e=Math.max(0,Math.min(e,1)),this.$fill.style.width=e*100+"%"}return this._inputFocused||(this.$input.value=this._decimals===void 0?t:t.toFixed(this._decimals)),this}_initInput(){this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("aria-labelledby",this.$name.id),window.matchMedia("(pointer: coarse)").matches&&(this.$input.setAttribute("type","number"),this.$input.setAttribute("step","any")),this.$widget.appendChild(this.$input),this.$disable=this.$input;const e=()=>{let x=parseFloat(this.$input.value);isNaN(x)||(this._stepExplicit&&(x=this._snap(x)),this.setValue(this._clamp(x)))},i=x=>{const A=parseFloat(this.$input.value);isNaN(A)||(this._snapClampSetValue(A+x),this.$input.value=this.getValue())},s=x=>{x.key==="Enter"&&this.$input.blur(),x.code==="ArrowUp"&&(x.preventDefault(),i(this._step*this._arrowKeyMultiplier(x))),x.code==="ArrowDown"&&(x.preventDefault(),i(this._step*this._arrowKeyMultiplier(x)*-1))},r=x=>{this._inputFocused&&(x.preventDefault(),i(this._step*this._normalizeMouseWheel(x)))};let a=!1,o,c,l,h,d;const u=5,m=x=>{o=x.clientX,c=l=x.clientY,a=!0,h=this.getValue(),d=0,window.addEventListener("mousemove",v),window.addEventListener("mouseup",M)},v=x=>{if(a){const A=x.clientX-o,y=x.clientY-c;Math.abs(y)>u?(x.preventDefault(),this.$input.blur(),a=!1,this._setDraggingStyle(!0,"vertical")):Math.abs(A)>u&&M()}if(!a){const A=x.clientY-l;d-=A*this._step*this._arrowKeyMultiplier(x),h+d>this._max?d=this._max-h:h+d<this._min&&(d=this._min-h),this._snapClampSetValue(h+d)}l=x.clientY},M=()=>{this._setDraggingStyle(!1,"vertical"),this._callOnFinishChange(),window.removeEventListener("mousemove",v),window.removeEventListener("mouseup",M)},p=()=>{this._inputFocused=!0},f=()=>{this._inputFocused=!1,this.updateDisplay(),this._callOnFinishChange()};this.$input.addEventListener("input",e),this.$input.addEventListener("keydown",s),this.$input.addEventListener("wheel",r,{passive:!1}),this.$input.addEventListener("mousedown",m),this.$input.addEventListener("focus",p),this.$input.addEventListener("blur",f)}_initSlider(){this._hasSlider=!0,this.$slider=document.createElement("div"),this.$slider.classList.add("lil-slider"),this.$fill=document.createElement("div"),this.$fill.classList.add("lil-fill"),this.$slider.appendChild(this.$fill),this.$widget.insertBefore(this.$slider,this.$input),this.domElement.classList.add("lil-has-slider");const t=(f,x,A,y,R)=>(f-x)/(A-x)*(R-y)+y,e=f=>{const x=this.$slider.getBoundingClientRect();let A=t(f,x.left,x.right,this._min,this._max);this._snapClampSetValue(A)},i=f=>{this._setDraggingStyle(!0),e(f.clientX),window.addEventListener("mousemove",s),window.addEventListener("mouseup",r)},s=f=>{e(f.clientX)},r=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("mousemove",s),window.removeEventListener("mouseup",r)};let a=!1,o,c;const l=f=>{f.preventDefault(),this._setDraggingStyle(!0),e(f.touches[0].clientX),a=!1},h=f=>{f.touches.length>1||(this._hasScrollBar?(o=f.touches[0].clientX,c=f.touches[0].clientY,a=!0):l(f),window.addEventListener("touchmove",d,{passive:!1}),window.addEventListener("touchend",u))},d=f=>{if(a){const x=f.touches[0].clientX-o,A=f.touches[0].clientY-c;Math.abs(x)>Math.abs(A)?l(f):(window.removeEventListener("touchmove",d),window.removeEventListener("touchend",u))}else f.preventDefault(),e(f.touches[0].clientX)},u=()=>{this._callOnFinishChange(),this._setDraggingStyle(!1),window.removeEventListener("touchmove",d),window.removeEventListener("touchend",u)},m=this._callOnFinishChange.bind(this),v=400;let M;const p=f=>{if(Math.abs(f.deltaX)<Math.abs(f.deltaY)&&this._hasScrollBar)return;f.preventDefault();const A=this._normalizeMouseWheel(f)*this._step;this._snapClampSetValue(this.getValue()+A),this.$input.value=this.getValue(),clearTimeout(M),M=setTimeout(m,v)};this.$slider.addEventListener("mousedown",i),this.$slider.addEventListener("touchstart",h,{passive:!1}),this.$slider.addEventListener("wheel",p,{passive:!1})}_setDraggingStyle(t,e="horizontal"){this.$slider&&this.$slider.classList.toggle("lil-active",t),document.body.classList.toggle("lil-dragging",t),document.body.classList.toggle(`lil-${e}`,t)}_getImplicitStep(){return this._hasMin&&this._hasMax?(this._max-this._min)/1e3:.1}_onUpdateMinMax(){!this._hasSlider&&this._hasMin&&this._hasMax&&(this._stepExplicit||this.step(this._getImplicitStep(),!1),this._initSlider(),this.updateDisplay())}_normalizeMouseWheel(t){let{deltaX:e,deltaY:i}=t;return Math.floor(t.deltaY)!==t.deltaY&&t.wheelDelta&&(e=0,i=-t.wheelDelta/120,i*=this._stepExplicit?1:10),e+-i}_arrowKeyMultiplier(t){let e=this._stepExplicit?1:10;return t.shiftKey?e*=10:t.altKey&&(e/=10),e}_snap(t){let e=0;return this._hasMin?e=this._min:this._hasMax&&(e=this._max),t-=e,t=Math.round(t/this._step)*this._step,t+=e,t=parseFloat(t.toPrecision(15)),t}_clamp(t){return t<this._min&&(t=this._min),t>this._max&&(t=this._max),t}_snapClampSetValue(t){this.setValue(this._clamp(this._snap(t)))}get _hasScrollBar(){const t=this.parent.root.$children;return t.scrollHeight>t.clientHeight}get _hasMin(){return this._min!==void 0}get _hasMax(){return this._max!==void 0}}class Ym extends zi{constructor(t,e,i,s){super(t,e,i,"lil-option"),this.$select=document.createElement("select"),this.$select.setAttribute("aria-labelledby",this.$name.id),this.$display=document.createElement("div"),this.$display.classList.add("lil-display"),this.$select.addEventListener("change",()=>{this.setValue(this._values[this.$select.selectedIndex]),this._callOnFinishChange()}),this.$select.addEventListener("focus",()=>{this.$display.classList.add("lil-focus")}),this.$select.addEventListener("blur",()=>{this.$display.classList.remove("lil-focus")}),this.$widget.appendChild(this.$select),this.$widget.appendChild(this.$display),this.$disable=this.$select,this.options(s)}options(t){return this._values=Array.isArray(t)?t:Object.values(t),this._names=Array.isArray(t)?t:Object.keys(t),this.$select.replaceChildren(),this._names.forEach(e=>{const i=document.createElement("option");i.textContent=e,this.$select.appendChild(i)}),this.updateDisplay(),this}updateDisplay(){const t=this.getValue(),e=this._values.indexOf(t);return this.$select.selectedIndex=e,this.$display.textContent=e===-1?t:this._names[e],this}}class qm extends zi{constructor(t,e,i){super(t,e,i,"lil-string"),this.$input=document.createElement("input"),this.$input.setAttribute("type","text"),this.$input.setAttribute("spellcheck","false"),this.$input.setAttribute("aria-labelledby",this.$name.id),this.$input.addEventListener("input",()=>{this.setValue(this.$input.value)}),this.$input.addEventListener("keydown",s=>{s.code==="Enter"&&this.$input.blur()}),this.$input.addEventListener("blur",()=>{this._callOnFinishChange()}),this.$widget.appendChild(this.$input),this.$disable=this.$input,this.updateDisplay()}updateDisplay(){return this.$input.value=this.getValue(),this}}var Km=`.lil-gui {
  font-family: var(--font-family);
  font-size: var(--font-size);
  line-height: 1;
  font-weight: normal;
  font-style: normal;
  text-align: left;
  color: var(--text-color);
  user-select: none;
  -webkit-user-select: none;
  touch-action: manipulation;
  --background-color: #1f1f1f;
  --text-color: #ebebeb;
  --title-background-color: #111111;
  --title-text-color: #ebebeb;
  --widget-color: #424242;
  --hover-color: #4f4f4f;
  --focus-color: #595959;
  --number-color: #2cc9ff;
  --string-color: #a2db3c;
  --font-size: 11px;
  --input-font-size: 11px;
  --font-family: -apple-system, BlinkMacSystemFont, "Segoe UI", Roboto, Arial, sans-serif;
  --font-family-mono: Menlo, Monaco, Consolas, "Droid Sans Mono", monospace;
  --padding: 4px;
  --spacing: 4px;
  --widget-height: 20px;
  --title-height: calc(var(--widget-height) + var(--spacing) * 1.25);
  --name-width: 45%;
  --slider-knob-width: 2px;
  --slider-input-width: 27%;
  --color-input-width: 27%;
  --slider-input-min-width: 45px;
  --color-input-min-width: 45px;
  --folder-indent: 7px;
  --widget-padding: 0 0 0 3px;
  --widget-border-radius: 2px;
  --checkbox-size: calc(0.75 * var(--widget-height));
  --scrollbar-width: 5px;
}
.lil-gui, .lil-gui * {
  box-sizing: border-box;
  margin: 0;
  padding: 0;
}
.lil-gui.lil-root {
  width: var(--width, 245px);
  display: flex;
  flex-direction: column;
  background: var(--background-color);
}
.lil-gui.lil-root > .lil-title {
  background: var(--title-background-color);
  color: var(--title-text-color);
}
.lil-gui.lil-root > .lil-children {
  overflow-x: hidden;
  overflow-y: auto;
}
.lil-gui.lil-root > .lil-children::-webkit-scrollbar {
  width: var(--scrollbar-width);
  height: var(--scrollbar-width);
  background: var(--background-color);
}
.lil-gui.lil-root > .lil-children::-webkit-scrollbar-thumb {
  border-radius: var(--scrollbar-width);
  background: var(--focus-color);
}
@media (pointer: coarse) {
  .lil-gui.lil-allow-touch-styles, .lil-gui.lil-allow-touch-styles .lil-gui {
    --widget-height: 28px;
    --padding: 6px;
    --spacing: 6px;
    --font-size: 13px;
    --input-font-size: 16px;
    --folder-indent: 10px;
    --scrollbar-width: 7px;
    --slider-input-min-width: 50px;
    --color-input-min-width: 65px;
  }
}
.lil-gui.lil-force-touch-styles, .lil-gui.lil-force-touch-styles .lil-gui {
  --widget-height: 28px;
  --padding: 6px;
  --spacing: 6px;
  --font-size: 13px;
  --input-font-size: 16px;
  --folder-indent: 10px;
  --scrollbar-width: 7px;
  --slider-input-min-width: 50px;
  --color-input-min-width: 65px;
}
.lil-gui.lil-auto-place, .lil-gui.autoPlace {
  max-height: 100%;
  position: fixed;
  top: 0;
  right: 15px;
  z-index: 1001;
}

.lil-controller {
  display: flex;
  align-items: center;
  padding: 0 var(--padding);
  margin: var(--spacing) 0;
}
.lil-controller.lil-disabled {
  opacity: 0.5;
}
.lil-controller.lil-disabled, .lil-controller.lil-disabled * {
  pointer-events: none !important;
}
.lil-controller > .lil-name {
  min-width: var(--name-width);
  flex-shrink: 0;
  white-space: pre;
  padding-right: var(--spacing);
  line-height: var(--widget-height);
}
.lil-controller .lil-widget {
  position: relative;
  display: flex;
  align-items: center;
  width: 100%;
  min-height: var(--widget-height);
}
.lil-controller.lil-string input {
  color: var(--string-color);
}
.lil-controller.lil-boolean {
  cursor: pointer;
}
.lil-controller.lil-color .lil-display {
  width: 100%;
  height: var(--widget-height);
  border-radius: var(--widget-border-radius);
  position: relative;
}
@media (hover: hover) {
  .lil-controller.lil-color .lil-display:hover:before {
    content: " ";
    display: block;
    position: absolute;
    border-radius: var(--widget-border-radius);
    border: 1px solid #fff9;
    top: 0;
    right: 0;
    bottom: 0;
    left: 0;
  }
}
.lil-controller.lil-color input[type=color] {
  opacity: 0;
  width: 100%;
  height: 100%;
  cursor: pointer;
}
.lil-controller.lil-color input[type=text] {
  margin-left: var(--spacing);
  font-family: var(--font-family-mono);
  min-width: var(--color-input-min-width);
  width: var(--color-input-width);
  flex-shrink: 0;
}
.lil-controller.lil-option select {
  opacity: 0;
  position: absolute;
  width: 100%;
  max-width: 100%;
}
.lil-controller.lil-option .lil-display {
  position: relative;
  pointer-events: none;
  border-radius: var(--widget-border-radius);
  height: var(--widget-height);
  line-height: var(--widget-height);
  max-width: 100%;
  overflow: hidden;
  word-break: break-all;
  padding-left: 0.55em;
  padding-right: 1.75em;
  background: var(--widget-color);
}
@media (hover: hover) {
  .lil-controller.lil-option .lil-display.lil-focus {
    background: var(--focus-color);
  }
}
.lil-controller.lil-option .lil-display.lil-active {
  background: var(--focus-color);
}
.lil-controller.lil-option .lil-display:after {
  font-family: "lil-gui";
  content: "↕";
  position: absolute;
  top: 0;
  right: 0;
  bottom: 0;
  padding-right: 0.375em;
}
.lil-controller.lil-option .lil-widget,
.lil-controller.lil-option select {
  cursor: pointer;
}
@media (hover: hover) {
  .lil-controller.lil-option .lil-widget:hover .lil-display {
    background: var(--hover-color);
  }
}
.lil-controller.lil-number input {
  color: var(--number-color);
}
.lil-controller.lil-number.lil-has-slider input {
  margin-left: var(--spacing);
  width: var(--slider-input-width);
  min-width: var(--slider-input-min-width);
  flex-shrink: 0;
}
.lil-controller.lil-number .lil-slider {
  width: 100%;
  height: var(--widget-height);
  background: var(--widget-color);
  border-radius: var(--widget-border-radius);
  padding-right: var(--slider-knob-width);
  overflow: hidden;
  cursor: ew-resize;
  touch-action: pan-y;
}
@media (hover: hover) {
  .lil-controller.lil-number .lil-slider:hover {
    background: var(--hover-color);
  }
}
.lil-controller.lil-number .lil-slider.lil-active {
  background: var(--focus-color);
}
.lil-controller.lil-number .lil-slider.lil-active .lil-fill {
  opacity: 0.95;
}
.lil-controller.lil-number .lil-fill {
  height: 100%;
  border-right: var(--slider-knob-width) solid var(--number-color);
  box-sizing: content-box;
}

.lil-dragging .lil-gui {
  --hover-color: var(--widget-color);
}
.lil-dragging * {
  cursor: ew-resize !important;
}
.lil-dragging.lil-vertical * {
  cursor: ns-resize !important;
}

.lil-gui .lil-title {
  height: var(--title-height);
  font-weight: 600;
  padding: 0 var(--padding);
  width: 100%;
  text-align: left;
  background: none;
  text-decoration-skip: objects;
}
.lil-gui .lil-title:before {
  font-family: "lil-gui";
  content: "▾";
  padding-right: 2px;
  display: inline-block;
}
.lil-gui .lil-title:active {
  background: var(--title-background-color);
  opacity: 0.75;
}
@media (hover: hover) {
  body:not(.lil-dragging) .lil-gui .lil-title:hover {
    background: var(--title-background-color);
    opacity: 0.85;
  }
  .lil-gui .lil-title:focus {
    text-decoration: underline var(--focus-color);
  }
}
.lil-gui.lil-root > .lil-title:focus {
  text-decoration: none !important;
}
.lil-gui.lil-closed > .lil-title:before {
  content: "▸";
}
.lil-gui.lil-closed > .lil-children {
  transform: translateY(-7px);
  opacity: 0;
}
.lil-gui.lil-closed:not(.lil-transition) > .lil-children {
  display: none;
}
.lil-gui.lil-transition > .lil-children {
  transition-duration: 300ms;
  transition-property: height, opacity, transform;
  transition-timing-function: cubic-bezier(0.2, 0.6, 0.35, 1);
  overflow: hidden;
  pointer-events: none;
}
.lil-gui .lil-children:empty:before {
  content: "Empty";
  padding: 0 var(--padding);
  margin: var(--spacing) 0;
  display: block;
  height: var(--widget-height);
  font-style: italic;
  line-height: var(--widget-height);
  opacity: 0.5;
}
.lil-gui.lil-root > .lil-children > .lil-gui > .lil-title {
  border: 0 solid var(--widget-color);
  border-width: 1px 0;
  transition: border-color 300ms;
}
.lil-gui.lil-root > .lil-children > .lil-gui.lil-closed > .lil-title {
  border-bottom-color: transparent;
}
.lil-gui + .lil-controller {
  border-top: 1px solid var(--widget-color);
  margin-top: 0;
  padding-top: var(--spacing);
}
.lil-gui .lil-gui .lil-gui > .lil-title {
  border: none;
}
.lil-gui .lil-gui .lil-gui > .lil-children {
  border: none;
  margin-left: var(--folder-indent);
  border-left: 2px solid var(--widget-color);
}
.lil-gui .lil-gui .lil-controller {
  border: none;
}

.lil-gui label, .lil-gui input, .lil-gui button {
  -webkit-tap-highlight-color: transparent;
}
.lil-gui input {
  border: 0;
  outline: none;
  font-family: var(--font-family);
  font-size: var(--input-font-size);
  border-radius: var(--widget-border-radius);
  height: var(--widget-height);
  background: var(--widget-color);
  color: var(--text-color);
  width: 100%;
}
@media (hover: hover) {
  .lil-gui input:hover {
    background: var(--hover-color);
  }
  .lil-gui input:active {
    background: var(--focus-color);
  }
}
.lil-gui input:disabled {
  opacity: 1;
}
.lil-gui input[type=text],
.lil-gui input[type=number] {
  padding: var(--widget-padding);
  -moz-appearance: textfield;
}
.lil-gui input[type=text]:focus,
.lil-gui input[type=number]:focus {
  background: var(--focus-color);
}
.lil-gui input[type=checkbox] {
  appearance: none;
  width: var(--checkbox-size);
  height: var(--checkbox-size);
  border-radius: var(--widget-border-radius);
  text-align: center;
  cursor: pointer;
}
.lil-gui input[type=checkbox]:checked:before {
  font-family: "lil-gui";
  content: "✓";
  font-size: var(--checkbox-size);
  line-height: var(--checkbox-size);
}
@media (hover: hover) {
  .lil-gui input[type=checkbox]:focus {
    box-shadow: inset 0 0 0 1px var(--focus-color);
  }
}
.lil-gui button {
  outline: none;
  cursor: pointer;
  font-family: var(--font-family);
  font-size: var(--font-size);
  color: var(--text-color);
  width: 100%;
  border: none;
}
.lil-gui .lil-controller button {
  height: var(--widget-height);
  text-transform: none;
  background: var(--widget-color);
  border-radius: var(--widget-border-radius);
}
@media (hover: hover) {
  .lil-gui .lil-controller button:hover {
    background: var(--hover-color);
  }
  .lil-gui .lil-controller button:focus {
    box-shadow: inset 0 0 0 1px var(--focus-color);
  }
}
.lil-gui .lil-controller button:active {
  background: var(--focus-color);
}

@font-face {
  font-family: "lil-gui";
  src: url("data:application/font-woff2;charset=utf-8;base64,d09GMgABAAAAAALkAAsAAAAABtQAAAKVAAEAAAAAAAAAAAAAAAAAAAAAAAAAAAAAHFQGYACDMgqBBIEbATYCJAMUCwwABCAFhAoHgQQbHAbIDiUFEYVARAAAYQTVWNmz9MxhEgodq49wYRUFKE8GWNiUBxI2LBRaVnc51U83Gmhs0Q7JXWMiz5eteLwrKwuxHO8VFxUX9UpZBs6pa5ABRwHA+t3UxUnH20EvVknRerzQgX6xC/GH6ZUvTcAjAv122dF28OTqCXrPuyaDER30YBA1xnkVutDDo4oCi71Ca7rrV9xS8dZHbPHefsuwIyCpmT7j+MnjAH5X3984UZoFFuJ0yiZ4XEJFxjagEBeqs+e1iyK8Xf/nOuwF+vVK0ur765+vf7txotUi0m3N0m/84RGSrBCNrh8Ee5GjODjF4gnWP+dJrH/Lk9k4oT6d+gr6g/wssA2j64JJGP6cmx554vUZnpZfn6ZfX2bMwPPrlANsB86/DiHjhl0OP+c87+gaJo/gY084s3HoYL/ZkWHTRfBXvvoHnnkHvngKun4KBE/ede7tvq3/vQOxDXB1/fdNz6XbPdcr0Vhpojj9dG+owuSKFsslCi1tgEjirjXdwMiov2EioadxmqTHUCIwo8NgQaeIasAi0fTYSPTbSmwbMOFduyh9wvBrESGY0MtgRjtgQR8Q1bRPohn2UoCRZf9wyYANMXFeJTysqAe0I4mrherOekFdKMrYvJjLvOIUM9SuwYB5DVZUwwVjJJOaUnZCmcEkIZZrKqNvRGRMvmFZsmhP4VMKCSXBhSqUBxgMS7h0cZvEd71AWkEhGWaeMFcNnpqyJkyXgYL7PQ1MoSq0wDAkRtJIijkZSmqYTiSImfLiSWXIZwhRh3Rug2X0kk1Dgj+Iu43u5p98ghopcpSo0Uyc8SnjlYX59WUeaMoDqmVD2TOWD9a4pCRAzf2ECgwGcrHjPOWY9bNxq/OL3I/QjwEAAAA=") format("woff2");
}`;function Zm(n){const t=document.createElement("style");t.innerHTML=n;const e=document.querySelector("head link[rel=stylesheet], head style");e?document.head.insertBefore(t,e):document.head.appendChild(t)}let hu=!1;class uh{constructor({parent:t,autoPlace:e=t===void 0,container:i,width:s,title:r="Controls",closeFolders:a=!1,injectStyles:o=!0,touchStyles:c=!0}={}){if(this.parent=t,this.root=t?t.root:this,this.children=[],this.controllers=[],this.folders=[],this._closed=!1,this._hidden=!1,this.domElement=document.createElement("div"),this.domElement.classList.add("lil-gui"),this.$title=document.createElement("button"),this.$title.classList.add("lil-title"),this.$title.setAttribute("aria-expanded",!0),this.$title.addEventListener("click",()=>this.openAnimated(this._closed)),this.$title.addEventListener("touchstart",()=>{},{passive:!0}),this.$children=document.createElement("div"),this.$children.classList.add("lil-children"),this.domElement.appendChild(this.$title),this.domElement.appendChild(this.$children),this.title(r),this.parent){this.parent.children.push(this),this.parent.folders.push(this),this.parent.$children.appendChild(this.domElement);return}this.domElement.classList.add("lil-root"),c&&this.domElement.classList.add("lil-allow-touch-styles"),!hu&&o&&(Zm(Km),hu=!0),i?i.appendChild(this.domElement):e&&(this.domElement.classList.add("lil-auto-place","autoPlace"),document.body.appendChild(this.domElement)),s&&this.domElement.style.setProperty("--width",s+"px"),this._closeFolders=a}add(t,e,i,s,r){if(Object(i)===i)return new Ym(this,t,e,i);const a=t[e];switch(typeof a){case"number":return new $m(this,t,e,i,s,r);case"boolean":return new zm(this,t,e);case"string":return new qm(this,t,e);case"function":return new ol(this,t,e)}console.error(`gui.add failed
	property:`,e,`
	object:`,t,`
	value:`,a)}addColor(t,e,i=1){return new Xm(this,t,e,i)}addFolder(t){const e=new uh({parent:this,title:t});return this.root._closeFolders&&e.close(),e}load(t,e=!0){return t.controllers&&this.controllers.forEach(i=>{i instanceof ol||i._name in t.controllers&&i.load(t.controllers[i._name])}),e&&t.folders&&this.folders.forEach(i=>{i._title in t.folders&&i.load(t.folders[i._title])}),this}save(t=!0){const e={controllers:{},folders:{}};return this.controllers.forEach(i=>{if(!(i instanceof ol)){if(i._name in e.controllers)throw new Error(`Cannot save GUI with duplicate property "${i._name}"`);e.controllers[i._name]=i.save()}}),t&&this.folders.forEach(i=>{if(i._title in e.folders)throw new Error(`Cannot save GUI with duplicate folder "${i._title}"`);e.folders[i._title]=i.save()}),e}open(t=!0){return this._setClosed(!t),this.$title.setAttribute("aria-expanded",!this._closed),this.domElement.classList.toggle("lil-closed",this._closed),this}close(){return this.open(!1)}_setClosed(t){this._closed!==t&&(this._closed=t,this._callOnOpenClose(this))}show(t=!0){return this._hidden=!t,this.domElement.style.display=this._hidden?"none":"",this}hide(){return this.show(!1)}openAnimated(t=!0){return this._setClosed(!t),this.$title.setAttribute("aria-expanded",!this._closed),requestAnimationFrame(()=>{const e=this.$children.clientHeight;this.$children.style.height=e+"px",this.domElement.classList.add("lil-transition");const i=r=>{r.target===this.$children&&(this.$children.style.height="",this.domElement.classList.remove("lil-transition"),this.$children.removeEventListener("transitionend",i))};this.$children.addEventListener("transitionend",i);const s=t?this.$children.scrollHeight:0;this.domElement.classList.toggle("lil-closed",!t),requestAnimationFrame(()=>{this.$children.style.height=s+"px"})}),this}title(t){return this._title=t,this.$title.textContent=t,this}reset(t=!0){return(t?this.controllersRecursive():this.controllers).forEach(i=>i.reset()),this}onChange(t){return this._onChange=t,this}_callOnChange(t){this.parent&&this.parent._callOnChange(t),this._onChange!==void 0&&this._onChange.call(this,{object:t.object,property:t.property,value:t.getValue(),controller:t})}onFinishChange(t){return this._onFinishChange=t,this}_callOnFinishChange(t){this.parent&&this.parent._callOnFinishChange(t),this._onFinishChange!==void 0&&this._onFinishChange.call(this,{object:t.object,property:t.property,value:t.getValue(),controller:t})}onOpenClose(t){return this._onOpenClose=t,this}_callOnOpenClose(t){this.parent&&this.parent._callOnOpenClose(t),this._onOpenClose!==void 0&&this._onOpenClose.call(this,t)}destroy(){this.parent&&(this.parent.children.splice(this.parent.children.indexOf(this),1),this.parent.folders.splice(this.parent.folders.indexOf(this),1)),this.domElement.parentElement&&this.domElement.parentElement.removeChild(this.domElement),Array.from(this.children).forEach(t=>t.destroy())}controllersRecursive(){let t=Array.from(this.controllers);return this.folders.forEach(e=>{t=t.concat(e.controllersRecursive())}),t}foldersRecursive(){let t=Array.from(this.folders);return this.folders.forEach(e=>{t=t.concat(e.foldersRecursive())}),t}}function Ef(n){return n==="1"?"":n.replace("^2","²").replace("^3","³")}function Jm(n){const t=Ef(n.unit);return t?`${n.name} [${t}]`:n.name}function oc(n){const t=Ef(n.unit),e=t?` ${t}`:"";return n.min!==null&&n.max!==null?`${n.min} … ${n.max}${e}`:n.min!==null?`≥ ${n.min}${e}`:n.max!==null?`≤ ${n.max}${e}`:"any finite number"}function Qm(n,t){return Number.isFinite(t)&&(n.min===null||t>=n.min)&&(n.max===null||t<=n.max)?null:`${n.name} = ${t} is not allowed: ${n.allowed??oc(n)} (${oc(n)})`}function bf(n,t,e,i,s){typeof t[e.name]!="number"&&(t[e.name]=e.default);const r=n.add(t,e.name,e.ui_min,e.ui_max).name(Jm(e)).onChange(o=>{const c=Qm(e,o);c!==null?s(c):i(o)});r.domElement.title=`${e.description} [${e.unit}]; allowed: ${oc(e)}; default ${e.default}`,r.domElement.dataset.param=e.name,r.step(e.step,!1);const a=r;return typeof a._clamp=="function"&&(a._clamp=o=>o),r}function dh(n,t){let e=-1/0,i=null,s=null;return(...r)=>{s=r;const a=e+t-performance.now();a<=0&&i===null?(e=performance.now(),n(...r),s=null):i===null&&(i=setTimeout(()=>{i=null,e=performance.now(),s!==null&&n(...s),s=null},Math.max(0,a)))}}function jm(n){const t={};for(const e of n)t[`${e.name} — ${e.summary}`]=e.name;return t}class tg{constructor(t,e,i){this.parent=t,this.schema=e,this.actions=i,this.picker=t.add(this.state,"model",jm(e.models)).name("model").onChange(s=>i.send({type:"set_model",model:s})),this.picker.domElement.dataset.control="model",this.picker.domElement.title=e.models.map(s=>`${s.name}: ${s.summary}`).join(`
`),this.sendParam=dh((s,r)=>{i.send({type:"set_params",params:{[s]:r}})},50)}parent;schema;actions;state={model:"ideal"};picker;paramsFolder=null;paramControls=[];values={};shown=null;sendParam;spec(t){return this.schema.models.find(e=>e.name===t)}rebuild(t){this.paramsFolder?.destroy(),this.paramsFolder=null,this.paramControls=[],this.values={},this.shown=t;const e=this.spec(t);if(e===void 0||e.params.length===0)return;const i=this.parent.addFolder(`${t} parameters`);for(const s of e.params){this.values[s.name]=s.default;const r=bf(i,this.values,s,a=>this.sendParam(s.name,a),this.actions.explain);this.paramControls.push(r)}this.paramsFolder=i}sync(t){const e=t.model??"ideal";this.state.model=e,this.picker.updateDisplay(),this.shown!==e&&this.rebuild(e);for(const[i,s]of Object.entries(t.model_params??{}))this.values[i]=s;for(const i of this.paramControls)i.domElement.contains(document.activeElement)||i.updateDisplay()}}const fh="187",yr={ROTATE:0,DOLLY:1,PAN:2},Sr={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},eg=0,uu=1,ng=2,_o=1,ig=2,sa=3,Es=0,Vn=1,ci=2,Er=0,ha=1,du=2,fu=3,pu=4,sg=5,vr=100,rg=101,ag=102,og=103,lg=104,cg=200,hg=201,ug=202,dg=203,wf=204,Tf=205,fg=206,pg=207,mg=208,gg=209,_g=210,vg=211,xg=212,Sg=213,Mg=214,lc=0,cc=1,hc=2,ga=3,uc=4,dc=5,fc=6,pc=7,Af=0,yg=1,Eg=2,ts=0,Rf=1,Cf=2,Pf=3,Lf=4,Df=5,Nf=6,If=7,Uf=300,Tr=301,_a=302,ll=303,cl=304,mc=1e3,ji=1001,gc=1002,wn=1003,bg=1004,Ia=1005,zn=1006,hl=1007,Ss=1008,Jn=1009,Ff=1010,Of=1011,va=1012,ph=1013,ki=1014,Bi=1015,Hi=1016,mh=1017,gh=1018,Ar=1020,Bf=35902,zf=35899,kf=1021,Hf=1022,Ei=1023,bs=1026,Ms=1027,Gf=1028,_h=1029,Ws=1030,vh=1031,xh=1033,vo=33776,xo=33777,So=33778,Mo=33779,_c=35840,vc=35841,xc=35842,Sc=35843,Mc=36196,yc=37492,Ec=37496,bc=37488,wc=37489,wo=37490,Tc=37491,Ac=37808,Rc=37809,Cc=37810,Pc=37811,Lc=37812,Dc=37813,Nc=37814,Ic=37815,Uc=37816,Fc=37817,Oc=37818,Bc=37819,zc=37820,kc=37821,Hc=36492,Gc=36494,Vc=36495,Wc=36283,Xc=36284,To=36285,$c=36286,wg=3200,Yc=0,Tg=1,xs="",ai="srgb",Ao="srgb-linear",Ro="linear",Ae="srgb",ul=7680,Ag=519,Rg=512,Cg=513,Pg=514,Vf=515,Lg=516,Dg=517,Wf=518,Xf=519,Ng=35044,mu="300 es",bi=2e3,xa=2001;function Ig(n){for(let t=n.length-1;t>=0;--t)if(n[t]>=65535)return!0;return!1}function Co(n){return document.createElementNS("http://www.w3.org/1999/xhtml",n)}function Ug(){const n=Co("canvas");return n.style.display="block",n}const gu={};function _u(...n){const t="THREE."+n.shift();console.log(t,...n)}function $f(n){const t=n[0];if(typeof t=="string"&&t.startsWith("TSL:")){const e=n[1];e&&e.isStackTrace?n[0]+=" "+e.getLocation():n[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return n}function Kt(...n){n=$f(n);const t="THREE."+n.shift();{const e=n[0];e&&e.isStackTrace?console.warn(e.getError(t)):console.warn(t,...n)}}function ve(...n){n=$f(n);const t="THREE."+n.shift();{const e=n[0];e&&e.isStackTrace?console.error(e.getError(t)):console.error(t,...n)}}function yo(...n){const t=n.join(" ");t in gu||(gu[t]=!0,Kt(...n))}function Fg(n,t,e){return new Promise(function(i,s){function r(){switch(n.clientWaitSync(t,n.SYNC_FLUSH_COMMANDS_BIT,0)){case n.WAIT_FAILED:s();break;case n.TIMEOUT_EXPIRED:setTimeout(r,e);break;default:i()}}setTimeout(r,e)})}const Og={[lc]:lc,[hc]:fc,[uc]:uc,[ga]:dc,[cc]:cc,[fc]:hc,[pc]:pc,[dc]:ga};class Cs{addEventListener(t,e){this._listeners===void 0&&(this._listeners={});const i=this._listeners;i[t]===void 0&&(i[t]=[]),i[t].indexOf(e)===-1&&i[t].push(e)}hasEventListener(t,e){const i=this._listeners;return i===void 0?!1:i[t]!==void 0&&i[t].indexOf(e)!==-1}removeEventListener(t,e){const i=this._listeners;if(i===void 0)return;const s=i[t];if(s!==void 0){const r=s.indexOf(e);r!==-1&&s.splice(r,1)}}dispatchEvent(t){const e=this._listeners;if(e===void 0)return;const i=e[t.type];if(i!==void 0){t.target=this;const s=i.slice(0);for(let r=0,a=s.length;r<a;r++)s[r].call(this,t);t.target=null}}}const Cn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],ua=Math.PI/180,Po=180/Math.PI;function ba(){const n=Math.random()*4294967295|0,t=Math.random()*4294967295|0,e=Math.random()*4294967295|0,i=Math.random()*4294967295|0;return(Cn[n&255]+Cn[n>>8&255]+Cn[n>>16&255]+Cn[n>>24&255]+"-"+Cn[t&255]+Cn[t>>8&255]+"-"+Cn[t>>16&15|64]+Cn[t>>24&255]+"-"+Cn[e&63|128]+Cn[e>>8&255]+"-"+Cn[e>>16&255]+Cn[e>>24&255]+Cn[i&255]+Cn[i>>8&255]+Cn[i>>16&255]+Cn[i>>24&255]).toLowerCase()}function de(n,t,e){return Math.max(t,Math.min(e,n))}function Bg(n,t){return(n%t+t)%t}function dl(n,t,e){return(1-e)*n+e*t}function zg(n){return Math.pow(2,Math.floor(Math.log(n)/Math.LN2))}function Sh(n){switch(n.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function kg(n,t){if(t.constructor===Float32Array)return n;const e=Sh(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(n/e,-1)}function Hg(n,t){if(t.constructor===Float32Array)return n;const e=Sh(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(n*e)}const Mh={DEG2RAD:ua,RAD2DEG:Po};class Jt{static{this.prototype.isVector2=!0}constructor(t=0,e=0){this.x=t,this.y=e}get width(){return this.x}set width(t){this.x=t}get height(){return this.y}set height(t){this.y=t}set(t,e){return this.x=t,this.y=e,this}setScalar(t){return this.x=t,this.y=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;default:throw new Error("THREE.Vector2: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y)}copy(t){return this.x=t.x,this.y=t.y,this}add(t){return this.x+=t.x,this.y+=t.y,this}addScalar(t){return this.x+=t,this.y+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this}subScalar(t){return this.x-=t,this.y-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this}multiply(t){return this.x*=t.x,this.y*=t.y,this}multiplyScalar(t){return this.x*=t,this.y*=t,this}divide(t){return this.x/=t.x,this.y/=t.y,this}divideScalar(t){return this.multiplyScalar(1/t)}applyMatrix3(t){const e=this.x,i=this.y,s=t.elements;return this.x=s[0]*e+s[3]*i+s[6],this.y=s[1]*e+s[4]*i+s[7],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this}clamp(t,e){return this.x=de(this.x,t.x,e.x),this.y=de(this.y,t.y,e.y),this}clampScalar(t,e){return this.x=de(this.x,t,e),this.y=de(this.y,t,e),this}clampLength(t,e){const i=this.length();return this.divideScalar(i||1).multiplyScalar(de(i,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(t){return this.x*t.x+this.y*t.y}cross(t){return this.x*t.y-this.y*t.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(t){const e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;const i=this.dot(t)/e;return Math.acos(de(i,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){const e=this.x-t.x,i=this.y-t.y;return e*e+i*i}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this}lerpVectors(t,e,i){return this.x=t.x+(e.x-t.x)*i,this.y=t.y+(e.y-t.y)*i,this}equals(t){return t.x===this.x&&t.y===this.y}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this}rotateAround(t,e){const i=Math.cos(e),s=Math.sin(e),r=this.x-t.x,a=this.y-t.y;return this.x=r*i-a*s+t.x,this.y=r*s+a*i+t.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}}class rs{constructor(t=0,e=0,i=0,s=1){this.isQuaternion=!0,this._x=t,this._y=e,this._z=i,this._w=s}static slerpFlat(t,e,i,s,r,a,o){let c=i[s+0],l=i[s+1],h=i[s+2],d=i[s+3],u=r[a+0],m=r[a+1],v=r[a+2],M=r[a+3];if(d!==M||c!==u||l!==m||h!==v){let p=c*u+l*m+h*v+d*M;p<0&&(u=-u,m=-m,v=-v,M=-M,p=-p);let f=1-o;if(p<.9995){const x=Math.acos(p),A=Math.sin(x);f=Math.sin(f*x)/A,o=Math.sin(o*x)/A,c=c*f+u*o,l=l*f+m*o,h=h*f+v*o,d=d*f+M*o}else{c=c*f+u*o,l=l*f+m*o,h=h*f+v*o,d=d*f+M*o;const x=1/Math.sqrt(c*c+l*l+h*h+d*d);c*=x,l*=x,h*=x,d*=x}}t[e]=c,t[e+1]=l,t[e+2]=h,t[e+3]=d}static multiplyQuaternionsFlat(t,e,i,s,r,a){const o=i[s],c=i[s+1],l=i[s+2],h=i[s+3],d=r[a],u=r[a+1],m=r[a+2],v=r[a+3];return t[e]=o*v+h*d+c*m-l*u,t[e+1]=c*v+h*u+l*d-o*m,t[e+2]=l*v+h*m+o*u-c*d,t[e+3]=h*v-o*d-c*u-l*m,t}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get w(){return this._w}set w(t){this._w=t,this._onChangeCallback()}set(t,e,i,s){return this._x=t,this._y=e,this._z=i,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(t){return this._x=t.x,this._y=t.y,this._z=t.z,this._w=t.w,this._onChangeCallback(),this}setFromEuler(t,e=!0){const i=t._x,s=t._y,r=t._z,a=t._order,o=Math.cos,c=Math.sin,l=o(i/2),h=o(s/2),d=o(r/2),u=c(i/2),m=c(s/2),v=c(r/2);switch(a){case"XYZ":this._x=u*h*d+l*m*v,this._y=l*m*d-u*h*v,this._z=l*h*v+u*m*d,this._w=l*h*d-u*m*v;break;case"YXZ":this._x=u*h*d+l*m*v,this._y=l*m*d-u*h*v,this._z=l*h*v-u*m*d,this._w=l*h*d+u*m*v;break;case"ZXY":this._x=u*h*d-l*m*v,this._y=l*m*d+u*h*v,this._z=l*h*v+u*m*d,this._w=l*h*d-u*m*v;break;case"ZYX":this._x=u*h*d-l*m*v,this._y=l*m*d+u*h*v,this._z=l*h*v-u*m*d,this._w=l*h*d+u*m*v;break;case"YZX":this._x=u*h*d+l*m*v,this._y=l*m*d+u*h*v,this._z=l*h*v-u*m*d,this._w=l*h*d-u*m*v;break;case"XZY":this._x=u*h*d-l*m*v,this._y=l*m*d-u*h*v,this._z=l*h*v+u*m*d,this._w=l*h*d+u*m*v;break;default:Kt("Quaternion: .setFromEuler() encountered an unknown order: "+a)}return e===!0&&this._onChangeCallback(),this}setFromAxisAngle(t,e){const i=e/2,s=Math.sin(i);return this._x=t.x*s,this._y=t.y*s,this._z=t.z*s,this._w=Math.cos(i),this._onChangeCallback(),this}setFromRotationMatrix(t){const e=t.elements,i=e[0],s=e[4],r=e[8],a=e[1],o=e[5],c=e[9],l=e[2],h=e[6],d=e[10],u=i+o+d;if(u>0){const m=.5/Math.sqrt(u+1);this._w=.25/m,this._x=(h-c)*m,this._y=(r-l)*m,this._z=(a-s)*m}else if(i>o&&i>d){const m=2*Math.sqrt(1+i-o-d);this._w=(h-c)/m,this._x=.25*m,this._y=(s+a)/m,this._z=(r+l)/m}else if(o>d){const m=2*Math.sqrt(1+o-i-d);this._w=(r-l)/m,this._x=(s+a)/m,this._y=.25*m,this._z=(c+h)/m}else{const m=2*Math.sqrt(1+d-i-o);this._w=(a-s)/m,this._x=(r+l)/m,this._y=(c+h)/m,this._z=.25*m}return this._onChangeCallback(),this}setFromUnitVectors(t,e){let i=t.dot(e)+1;return i<1e-8?(i=0,Math.abs(t.x)>Math.abs(t.z)?(this._x=-t.y,this._y=t.x,this._z=0,this._w=i):(this._x=0,this._y=-t.z,this._z=t.y,this._w=i)):(this._x=t.y*e.z-t.z*e.y,this._y=t.z*e.x-t.x*e.z,this._z=t.x*e.y-t.y*e.x,this._w=i),this.normalize()}angleTo(t){return 2*Math.acos(Math.abs(de(this.dot(t),-1,1)))}rotateTowards(t,e){const i=this.angleTo(t);if(i===0)return this;const s=Math.min(1,e/i);return this.slerp(t,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(t){return this._x*t._x+this._y*t._y+this._z*t._z+this._w*t._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let t=this.length();return t===0?(this._x=0,this._y=0,this._z=0,this._w=1):(t=1/t,this._x=this._x*t,this._y=this._y*t,this._z=this._z*t,this._w=this._w*t),this._onChangeCallback(),this}multiply(t){return this.multiplyQuaternions(this,t)}premultiply(t){return this.multiplyQuaternions(t,this)}multiplyQuaternions(t,e){const i=t._x,s=t._y,r=t._z,a=t._w,o=e._x,c=e._y,l=e._z,h=e._w;return this._x=i*h+a*o+s*l-r*c,this._y=s*h+a*c+r*o-i*l,this._z=r*h+a*l+i*c-s*o,this._w=a*h-i*o-s*c-r*l,this._onChangeCallback(),this}slerp(t,e){let i=t._x,s=t._y,r=t._z,a=t._w,o=this.dot(t);o<0&&(i=-i,s=-s,r=-r,a=-a,o=-o);let c=1-e;if(o<.9995){const l=Math.acos(o),h=Math.sin(l);c=Math.sin(c*l)/h,e=Math.sin(e*l)/h,this._x=this._x*c+i*e,this._y=this._y*c+s*e,this._z=this._z*c+r*e,this._w=this._w*c+a*e,this._onChangeCallback()}else this._x=this._x*c+i*e,this._y=this._y*c+s*e,this._z=this._z*c+r*e,this._w=this._w*c+a*e,this.normalize();return this}slerpQuaternions(t,e,i){return this.copy(t).slerp(e,i)}random(){const t=2*Math.PI*Math.random(),e=2*Math.PI*Math.random(),i=Math.random(),s=Math.sqrt(1-i),r=Math.sqrt(i);return this.set(s*Math.sin(t),s*Math.cos(t),r*Math.sin(e),r*Math.cos(e))}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._w===this._w}fromArray(t,e=0){return this._x=t[e],this._y=t[e+1],this._z=t[e+2],this._w=t[e+3],this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._w,t}fromBufferAttribute(t,e){return this._x=t.getX(e),this._y=t.getY(e),this._z=t.getZ(e),this._w=t.getW(e),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}}class V{static{this.prototype.isVector3=!0}constructor(t=0,e=0,i=0){this.x=t,this.y=e,this.z=i}set(t,e,i){return i===void 0&&(i=this.z),this.x=t,this.y=e,this.z=i,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;default:throw new Error("THREE.Vector3: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this}multiplyVectors(t,e){return this.x=t.x*e.x,this.y=t.y*e.y,this.z=t.z*e.z,this}applyEuler(t){return this.applyQuaternion(vu.setFromEuler(t))}applyAxisAngle(t,e){return this.applyQuaternion(vu.setFromAxisAngle(t,e))}applyMatrix3(t){const e=this.x,i=this.y,s=this.z,r=t.elements;return this.x=r[0]*e+r[3]*i+r[6]*s,this.y=r[1]*e+r[4]*i+r[7]*s,this.z=r[2]*e+r[5]*i+r[8]*s,this}applyNormalMatrix(t){return this.applyMatrix3(t).normalize()}applyMatrix4(t){const e=this.x,i=this.y,s=this.z,r=t.elements,a=1/(r[3]*e+r[7]*i+r[11]*s+r[15]);return this.x=(r[0]*e+r[4]*i+r[8]*s+r[12])*a,this.y=(r[1]*e+r[5]*i+r[9]*s+r[13])*a,this.z=(r[2]*e+r[6]*i+r[10]*s+r[14])*a,this}applyQuaternion(t){const e=this.x,i=this.y,s=this.z,r=t.x,a=t.y,o=t.z,c=t.w,l=2*(a*s-o*i),h=2*(o*e-r*s),d=2*(r*i-a*e);return this.x=e+c*l+a*d-o*h,this.y=i+c*h+o*l-r*d,this.z=s+c*d+r*h-a*l,this}project(t){return this.applyMatrix4(t.matrixWorldInverse).applyMatrix4(t.projectionMatrix)}unproject(t){return this.applyMatrix4(t.projectionMatrixInverse).applyMatrix4(t.matrixWorld)}transformDirection(t){const e=this.x,i=this.y,s=this.z,r=t.elements;return this.x=r[0]*e+r[4]*i+r[8]*s,this.y=r[1]*e+r[5]*i+r[9]*s,this.z=r[2]*e+r[6]*i+r[10]*s,this.normalize()}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this}divideScalar(t){return this.multiplyScalar(1/t)}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this}clamp(t,e){return this.x=de(this.x,t.x,e.x),this.y=de(this.y,t.y,e.y),this.z=de(this.z,t.z,e.z),this}clampScalar(t,e){return this.x=de(this.x,t,e),this.y=de(this.y,t,e),this.z=de(this.z,t,e),this}clampLength(t,e){const i=this.length();return this.divideScalar(i||1).multiplyScalar(de(i,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this}lerpVectors(t,e,i){return this.x=t.x+(e.x-t.x)*i,this.y=t.y+(e.y-t.y)*i,this.z=t.z+(e.z-t.z)*i,this}cross(t){return this.crossVectors(this,t)}crossVectors(t,e){const i=t.x,s=t.y,r=t.z,a=e.x,o=e.y,c=e.z;return this.x=s*c-r*o,this.y=r*a-i*c,this.z=i*o-s*a,this}projectOnVector(t){const e=t.lengthSq();if(e===0)return this.set(0,0,0);const i=t.dot(this)/e;return this.copy(t).multiplyScalar(i)}projectOnPlane(t){return fl.copy(this).projectOnVector(t),this.sub(fl)}reflect(t){return this.sub(fl.copy(t).multiplyScalar(2*this.dot(t)))}angleTo(t){const e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;const i=this.dot(t)/e;return Math.acos(de(i,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){const e=this.x-t.x,i=this.y-t.y,s=this.z-t.z;return e*e+i*i+s*s}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)+Math.abs(this.z-t.z)}setFromSpherical(t){return this.setFromSphericalCoords(t.radius,t.phi,t.theta)}setFromSphericalCoords(t,e,i){const s=Math.sin(e)*t;return this.x=s*Math.sin(i),this.y=Math.cos(e)*t,this.z=s*Math.cos(i),this}setFromCylindrical(t){return this.setFromCylindricalCoords(t.radius,t.theta,t.y)}setFromCylindricalCoords(t,e,i){return this.x=t*Math.sin(e),this.y=i,this.z=t*Math.cos(e),this}setFromMatrixPosition(t){const e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this}setFromMatrixScale(t){const e=this.setFromMatrixColumn(t,0).length(),i=this.setFromMatrixColumn(t,1).length(),s=this.setFromMatrixColumn(t,2).length();return this.x=e,this.y=i,this.z=s,this}setFromMatrixColumn(t,e){return this.fromArray(t.elements,e*4)}setFromMatrix3Column(t,e){return this.fromArray(t.elements,e*3)}setFromEuler(t){return this.x=t._x,this.y=t._y,this.z=t._z,this}setFromColor(t){return this.x=t.r,this.y=t.g,this.z=t.b,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){const t=Math.random()*Math.PI*2,e=Math.random()*2-1,i=Math.sqrt(1-e*e);return this.x=i*Math.cos(t),this.y=e,this.z=i*Math.sin(t),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}}const fl=new V,vu=new rs;class te{static{this.prototype.isMatrix3=!0}constructor(t,e,i,s,r,a,o,c,l){this.elements=[1,0,0,0,1,0,0,0,1],t!==void 0&&this.set(t,e,i,s,r,a,o,c,l)}set(t,e,i,s,r,a,o,c,l){const h=this.elements;return h[0]=t,h[1]=s,h[2]=o,h[3]=e,h[4]=r,h[5]=c,h[6]=i,h[7]=a,h[8]=l,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(t){const e=this.elements,i=t.elements;return e[0]=i[0],e[1]=i[1],e[2]=i[2],e[3]=i[3],e[4]=i[4],e[5]=i[5],e[6]=i[6],e[7]=i[7],e[8]=i[8],this}extractBasis(t,e,i){return t.setFromMatrix3Column(this,0),e.setFromMatrix3Column(this,1),i.setFromMatrix3Column(this,2),this}setFromMatrix4(t){const e=t.elements;return this.set(e[0],e[4],e[8],e[1],e[5],e[9],e[2],e[6],e[10]),this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){const i=t.elements,s=e.elements,r=this.elements,a=i[0],o=i[3],c=i[6],l=i[1],h=i[4],d=i[7],u=i[2],m=i[5],v=i[8],M=s[0],p=s[3],f=s[6],x=s[1],A=s[4],y=s[7],R=s[2],E=s[5],g=s[8];return r[0]=a*M+o*x+c*R,r[3]=a*p+o*A+c*E,r[6]=a*f+o*y+c*g,r[1]=l*M+h*x+d*R,r[4]=l*p+h*A+d*E,r[7]=l*f+h*y+d*g,r[2]=u*M+m*x+v*R,r[5]=u*p+m*A+v*E,r[8]=u*f+m*y+v*g,this}multiplyScalar(t){const e=this.elements;return e[0]*=t,e[3]*=t,e[6]*=t,e[1]*=t,e[4]*=t,e[7]*=t,e[2]*=t,e[5]*=t,e[8]*=t,this}determinant(){const t=this.elements,e=t[0],i=t[1],s=t[2],r=t[3],a=t[4],o=t[5],c=t[6],l=t[7],h=t[8];return e*a*h-e*o*l-i*r*h+i*o*c+s*r*l-s*a*c}invert(){const t=this.elements,e=t[0],i=t[1],s=t[2],r=t[3],a=t[4],o=t[5],c=t[6],l=t[7],h=t[8],d=h*a-o*l,u=o*c-h*r,m=l*r-a*c,v=e*d+i*u+s*m;if(v===0)return this.set(0,0,0,0,0,0,0,0,0);const M=1/v;return t[0]=d*M,t[1]=(s*l-h*i)*M,t[2]=(o*i-s*a)*M,t[3]=u*M,t[4]=(h*e-s*c)*M,t[5]=(s*r-o*e)*M,t[6]=m*M,t[7]=(i*c-l*e)*M,t[8]=(a*e-i*r)*M,this}transpose(){let t;const e=this.elements;return t=e[1],e[1]=e[3],e[3]=t,t=e[2],e[2]=e[6],e[6]=t,t=e[5],e[5]=e[7],e[7]=t,this}getNormalMatrix(t){return this.setFromMatrix4(t).invert().transpose()}transposeIntoArray(t){const e=this.elements;return t[0]=e[0],t[1]=e[3],t[2]=e[6],t[3]=e[1],t[4]=e[4],t[5]=e[7],t[6]=e[2],t[7]=e[5],t[8]=e[8],this}setUvTransform(t,e,i,s,r,a,o){const c=Math.cos(r),l=Math.sin(r);return this.set(i*c,i*l,-i*(c*a+l*o)+a+t,-s*l,s*c,-s*(-l*a+c*o)+o+e,0,0,1),this}scale(t,e){return yo("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(pl.makeScale(t,e)),this}rotate(t){return yo("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(pl.makeRotation(-t)),this}translate(t,e){return yo("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(pl.makeTranslation(t,e)),this}makeTranslation(t,e){return t.isVector2?this.set(1,0,t.x,0,1,t.y,0,0,1):this.set(1,0,t,0,1,e,0,0,1),this}makeRotation(t){const e=Math.cos(t),i=Math.sin(t);return this.set(e,-i,0,i,e,0,0,0,1),this}makeScale(t,e){return this.set(t,0,0,0,e,0,0,0,1),this}equals(t){const e=this.elements,i=t.elements;for(let s=0;s<9;s++)if(e[s]!==i[s])return!1;return!0}fromArray(t,e=0){for(let i=0;i<9;i++)this.elements[i]=t[i+e];return this}toArray(t=[],e=0){const i=this.elements;return t[e]=i[0],t[e+1]=i[1],t[e+2]=i[2],t[e+3]=i[3],t[e+4]=i[4],t[e+5]=i[5],t[e+6]=i[6],t[e+7]=i[7],t[e+8]=i[8],t}clone(){return new this.constructor().fromArray(this.elements)}}const pl=new te,xu=new te().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Su=new te().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function Gg(){const n={enabled:!0,workingColorSpace:Ao,spaces:{},convert:function(s,r,a){return this.enabled===!1||r===a||!r||!a||(this.spaces[r].transfer===Ae&&(s.r=es(s.r),s.g=es(s.g),s.b=es(s.b)),this.spaces[r].primaries!==this.spaces[a].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[a].fromXYZ)),this.spaces[a].transfer===Ae&&(s.r=br(s.r),s.g=br(s.g),s.b=br(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===xs?Ro:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,a){return s.copy(this.spaces[a].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},t=[.64,.33,.3,.6,.15,.06],e=[.2126,.7152,.0722],i=[.3127,.329];return n.define({[Ao]:{primaries:t,whitePoint:i,transfer:Ro,toXYZ:xu,fromXYZ:Su,luminanceCoefficients:e,workingColorSpaceConfig:{unpackColorSpace:ai},outputColorSpaceConfig:{drawingBufferColorSpace:ai}},[ai]:{primaries:t,whitePoint:i,transfer:Ae,toXYZ:xu,fromXYZ:Su,luminanceCoefficients:e,outputColorSpaceConfig:{drawingBufferColorSpace:ai}}}),n}const me=Gg();function es(n){return n<.04045?n*.0773993808:Math.pow(n*.9478672986+.0521327014,2.4)}function br(n){return n<.0031308?n*12.92:1.055*Math.pow(n,.41666)-.055}let rr;class Vg{static getDataURL(t,e="image/png"){if(/^data:/i.test(t.src)||typeof HTMLCanvasElement>"u")return t.src;let i;if(t instanceof HTMLCanvasElement)i=t;else{rr===void 0&&(rr=Co("canvas")),rr.width=t.width,rr.height=t.height;const s=rr.getContext("2d");t instanceof ImageData?s.putImageData(t,0,0):s.drawImage(t,0,0,t.width,t.height),i=rr}return i.toDataURL(e)}static sRGBToLinear(t){if(typeof HTMLImageElement<"u"&&t instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&t instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&t instanceof ImageBitmap){const e=Co("canvas");e.width=t.width,e.height=t.height;const i=e.getContext("2d");i.drawImage(t,0,0,t.width,t.height);const s=i.getImageData(0,0,t.width,t.height),r=s.data;for(let a=0;a<r.length;a++)r[a]=es(r[a]/255)*255;return i.putImageData(s,0,0),e}else if(t.data){const e=t.data.slice(0);for(let i=0;i<e.length;i++)e instanceof Uint8Array||e instanceof Uint8ClampedArray?e[i]=Math.floor(es(e[i]/255)*255):e[i]=es(e[i]);return{data:e,width:t.width,height:t.height}}else return Kt("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),t}}let Wg=0;class yh{constructor(t=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:Wg++}),this.uuid=ba(),this.data=t,this.dataReady=!0,this.version=0}getSize(t){const e=this.data;return typeof HTMLVideoElement<"u"&&e instanceof HTMLVideoElement?t.set(e.videoWidth,e.videoHeight,0):typeof VideoFrame<"u"&&e instanceof VideoFrame?t.set(e.displayWidth,e.displayHeight,0):e!==null?t.set(e.width||0,e.height||0,e.depth||0):t.set(0,0,0),t}set needsUpdate(t){t===!0&&this.version++}toJSON(t){const e=t===void 0||typeof t=="string";if(!e&&t.images[this.uuid]!==void 0)return t.images[this.uuid];const i={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let a=0,o=s.length;a<o;a++)s[a].isDataTexture?r.push(ml(s[a].image)):r.push(ml(s[a]))}else r=ml(s);i.url=r}return e||(t.images[this.uuid]=i),i}}function ml(n){return typeof HTMLImageElement<"u"&&n instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&n instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&n instanceof ImageBitmap?Vg.getDataURL(n):n.data?{data:Array.from(n.data),width:n.width,height:n.height,type:n.data.constructor.name}:(Kt("Texture: Unable to serialize Texture."),{})}let Xg=0;const gl=new V;class Hn extends Cs{constructor(t=Hn.DEFAULT_IMAGE,e=Hn.DEFAULT_MAPPING,i=ji,s=ji,r=zn,a=Ss,o=Ei,c=Jn,l=Hn.DEFAULT_ANISOTROPY,h=xs){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:Xg++}),this.uuid=ba(),this.name="",this.source=new yh(t),this.mipmaps=[],this.mapping=e,this.channel=0,this.wrapS=i,this.wrapT=s,this.magFilter=r,this.minFilter=a,this.anisotropy=l,this.format=o,this.internalFormat=null,this.type=c,this.offset=new Jt(0,0),this.repeat=new Jt(1,1),this.center=new Jt(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new te,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(t&&t.depth&&t.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(gl).x}get height(){return this.source.getSize(gl).y}get depth(){return this.source.getSize(gl).z}get image(){return this.source.data}set image(t){this.source.data=t}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(t){return this.name=t.name,this.source=t.source,this.mipmaps=t.mipmaps.slice(0),this.mapping=t.mapping,this.channel=t.channel,this.wrapS=t.wrapS,this.wrapT=t.wrapT,this.magFilter=t.magFilter,this.minFilter=t.minFilter,this.anisotropy=t.anisotropy,this.format=t.format,this.internalFormat=t.internalFormat,this.type=t.type,this.normalized=t.normalized,this.offset.copy(t.offset),this.repeat.copy(t.repeat),this.center.copy(t.center),this.rotation=t.rotation,this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrix.copy(t.matrix),this.generateMipmaps=t.generateMipmaps,this.mipmapsAutoUpdate=t.mipmapsAutoUpdate,this.premultiplyAlpha=t.premultiplyAlpha,this.flipY=t.flipY,this.unpackAlignment=t.unpackAlignment,this.colorSpace=t.colorSpace,this.renderTarget=t.renderTarget,this.isRenderTargetTexture=t.isRenderTargetTexture,this.isPMREMTexture=t.isPMREMTexture,this.isArrayTexture=t.isArrayTexture,this.userData=JSON.parse(JSON.stringify(t.userData)),this.needsUpdate=!0,this}setValues(t){for(const e in t){const i=t[e];if(i===void 0){Kt(`Texture.setValues(): parameter '${e}' has value of undefined.`);continue}const s=this[e];if(s===void 0){Kt(`Texture.setValues(): property '${e}' does not exist.`);continue}s&&i&&s.isVector2&&i.isVector2||s&&i&&s.isVector3&&i.isVector3||s&&i&&s.isMatrix3&&i.isMatrix3?s.copy(i):this[e]=i}}toJSON(t){const e=t===void 0||typeof t=="string";if(!e&&t.textures[this.uuid]!==void 0)return t.textures[this.uuid];const i={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(t).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(i.userData=this.userData),e||(t.textures[this.uuid]=i),i}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(t){if(this.mapping!==Uf)return t;if(t.applyMatrix3(this.matrix),t.x<0||t.x>1)switch(this.wrapS){case mc:t.x=t.x-Math.floor(t.x);break;case ji:t.x=t.x<0?0:1;break;case gc:Math.abs(Math.floor(t.x)%2)===1?t.x=Math.ceil(t.x)-t.x:t.x=t.x-Math.floor(t.x);break}if(t.y<0||t.y>1)switch(this.wrapT){case mc:t.y=t.y-Math.floor(t.y);break;case ji:t.y=t.y<0?0:1;break;case gc:Math.abs(Math.floor(t.y)%2)===1?t.y=Math.ceil(t.y)-t.y:t.y=t.y-Math.floor(t.y);break}return this.flipY&&(t.y=1-t.y),t}set needsUpdate(t){t===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(t){t===!0&&this.pmremVersion++}}Hn.DEFAULT_IMAGE=null;Hn.DEFAULT_MAPPING=Uf;Hn.DEFAULT_ANISOTROPY=1;class Qe{static{this.prototype.isVector4=!0}constructor(t=0,e=0,i=0,s=1){this.x=t,this.y=e,this.z=i,this.w=s}get width(){return this.z}set width(t){this.z=t}get height(){return this.w}set height(t){this.w=t}set(t,e,i,s){return this.x=t,this.y=e,this.z=i,this.w=s,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this.w=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setW(t){return this.w=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;case 3:this.w=e;break;default:throw new Error("THREE.Vector4: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this.w=t.w!==void 0?t.w:1,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this.w+=t.w,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this.w+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this.w=t.w+e.w,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this.w+=t.w*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this.w-=t.w,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this.w-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this.w=t.w-e.w,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this.w*=t.w,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this.w*=t,this}applyMatrix4(t){const e=this.x,i=this.y,s=this.z,r=this.w,a=t.elements;return this.x=a[0]*e+a[4]*i+a[8]*s+a[12]*r,this.y=a[1]*e+a[5]*i+a[9]*s+a[13]*r,this.z=a[2]*e+a[6]*i+a[10]*s+a[14]*r,this.w=a[3]*e+a[7]*i+a[11]*s+a[15]*r,this}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this.w/=t.w,this}divideScalar(t){return this.multiplyScalar(1/t)}setAxisAngleFromQuaternion(t){this.w=2*Math.acos(t.w);const e=Math.sqrt(1-t.w*t.w);return e<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=t.x/e,this.y=t.y/e,this.z=t.z/e),this}setAxisAngleFromRotationMatrix(t){let e,i,s,r;const c=t.elements,l=c[0],h=c[4],d=c[8],u=c[1],m=c[5],v=c[9],M=c[2],p=c[6],f=c[10];if(Math.abs(h-u)<.01&&Math.abs(d-M)<.01&&Math.abs(v-p)<.01){if(Math.abs(h+u)<.1&&Math.abs(d+M)<.1&&Math.abs(v+p)<.1&&Math.abs(l+m+f-3)<.1)return this.set(1,0,0,0),this;e=Math.PI;const A=(l+1)/2,y=(m+1)/2,R=(f+1)/2,E=(h+u)/4,g=(d+M)/4,T=(v+p)/4;return A>y&&A>R?A<.01?(i=0,s=.707106781,r=.707106781):(i=Math.sqrt(A),s=E/i,r=g/i):y>R?y<.01?(i=.707106781,s=0,r=.707106781):(s=Math.sqrt(y),i=E/s,r=T/s):R<.01?(i=.707106781,s=.707106781,r=0):(r=Math.sqrt(R),i=g/r,s=T/r),this.set(i,s,r,e),this}let x=Math.sqrt((p-v)*(p-v)+(d-M)*(d-M)+(u-h)*(u-h));return Math.abs(x)<.001&&(x=1),this.x=(p-v)/x,this.y=(d-M)/x,this.z=(u-h)/x,this.w=Math.acos((l+m+f-1)/2),this}setFromMatrixPosition(t){const e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this.w=e[15],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this.w=Math.min(this.w,t.w),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this.w=Math.max(this.w,t.w),this}clamp(t,e){return this.x=de(this.x,t.x,e.x),this.y=de(this.y,t.y,e.y),this.z=de(this.z,t.z,e.z),this.w=de(this.w,t.w,e.w),this}clampScalar(t,e){return this.x=de(this.x,t,e),this.y=de(this.y,t,e),this.z=de(this.z,t,e),this.w=de(this.w,t,e),this}clampLength(t,e){const i=this.length();return this.divideScalar(i||1).multiplyScalar(de(i,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z+this.w*t.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this.w+=(t.w-this.w)*e,this}lerpVectors(t,e,i){return this.x=t.x+(e.x-t.x)*i,this.y=t.y+(e.y-t.y)*i,this.z=t.z+(e.z-t.z)*i,this.w=t.w+(e.w-t.w)*i,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z&&t.w===this.w}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this.w=t[e+3],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t[e+3]=this.w,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this.w=t.getW(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}}class $g extends Cs{constructor(t=1,e=1,i={}){super(),i=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:zn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},i),this.isRenderTarget=!0,this.width=t,this.height=e,this.depth=i.depth,this.scissor=new Qe(0,0,t,e),this.scissorTest=!1,this.viewport=new Qe(0,0,t,e),this.textures=[];const s=i.count;for(let r=0;r<s;r++)this.textures[r]=new Hn({width:t,height:e,depth:i.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(i),this.depthBuffer=i.depthBuffer,this.stencilBuffer=i.stencilBuffer,this.resolveColorBuffer=i.resolveColorBuffer,this.resolveDepthBuffer=i.resolveDepthBuffer,this.resolveStencilBuffer=i.resolveStencilBuffer,this.storeMultisampledColorBuffer=i.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=i.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=i.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=i.depthTexture,this.samples=i.samples,this.multiview=i.multiview,this.useArrayDepthTexture=i.useArrayDepthTexture}_setTextureOptions(t={}){const e={minFilter:zn,generateMipmaps:!1,flipY:!1,internalFormat:null};t.mapping!==void 0&&(e.mapping=t.mapping),t.wrapS!==void 0&&(e.wrapS=t.wrapS),t.wrapT!==void 0&&(e.wrapT=t.wrapT),t.wrapR!==void 0&&(e.wrapR=t.wrapR),t.magFilter!==void 0&&(e.magFilter=t.magFilter),t.minFilter!==void 0&&(e.minFilter=t.minFilter),t.format!==void 0&&(e.format=t.format),t.type!==void 0&&(e.type=t.type),t.anisotropy!==void 0&&(e.anisotropy=t.anisotropy),t.colorSpace!==void 0&&(e.colorSpace=t.colorSpace),t.flipY!==void 0&&(e.flipY=t.flipY),t.generateMipmaps!==void 0&&(e.generateMipmaps=t.generateMipmaps),t.mipmapsAutoUpdate!==void 0&&(e.mipmapsAutoUpdate=t.mipmapsAutoUpdate),t.internalFormat!==void 0&&(e.internalFormat=t.internalFormat);for(let i=0;i<this.textures.length;i++)this.textures[i].setValues(e)}get texture(){return this.textures[0]}set texture(t){this.textures[0]=t}set depthTexture(t){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),t!==null&&t.renderTarget===null&&(t.renderTarget=this),this._depthTexture=t}get depthTexture(){return this._depthTexture}setSize(t,e,i=1){if(this.width!==t||this.height!==e||this.depth!==i){this.width=t,this.height=e,this.depth=i;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=t,this.textures[s].image.height=e,this.textures[s].image.depth=i,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,t,e),this.scissor.set(0,0,t,e)}clone(){return new this.constructor().copy(this)}copy(t){this.width=t.width,this.height=t.height,this.depth=t.depth,this.scissor.copy(t.scissor),this.scissorTest=t.scissorTest,this.viewport.copy(t.viewport),this.textures.length=0;for(let e=0,i=t.textures.length;e<i;e++){this.textures[e]=t.textures[e].clone(),this.textures[e].isRenderTargetTexture=!0,this.textures[e].renderTarget=this;const s=Object.assign({},t.textures[e].image);this.textures[e].source=new yh(s)}if(this.depthBuffer=t.depthBuffer,this.stencilBuffer=t.stencilBuffer,this.resolveColorBuffer=t.resolveColorBuffer,this.resolveDepthBuffer=t.resolveDepthBuffer,this.resolveStencilBuffer=t.resolveStencilBuffer,this.storeMultisampledColorBuffer=t.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=t.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=t.storeMultisampledStencilBuffer,t.depthTexture!==null)if(t.depthTexture.renderTarget===t){const e=t.depthTexture.clone();e.renderTarget=null,this.depthTexture=e}else this.depthTexture=t.depthTexture;else this.depthTexture=null;return this.samples=t.samples,this.multiview=t.multiview,this.useArrayDepthTexture=t.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}}class hi extends $g{constructor(t=1,e=1,i={}){super(t,e,i),this.isWebGLRenderTarget=!0}}class Yf extends Hn{constructor(t=null,e=1,i=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:t,width:e,height:i,depth:s},this.magFilter=wn,this.minFilter=wn,this.wrapR=ji,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}addLayerUpdate(t){this.layerUpdates.add(t)}clearLayerUpdates(){this.layerUpdates.clear()}}class Yg extends Hn{constructor(t=null,e=1,i=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:t,width:e,height:i,depth:s},this.magFilter=wn,this.minFilter=wn,this.wrapR=ji,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}}class Le{static{this.prototype.isMatrix4=!0}constructor(t,e,i,s,r,a,o,c,l,h,d,u,m,v,M,p){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],t!==void 0&&this.set(t,e,i,s,r,a,o,c,l,h,d,u,m,v,M,p)}set(t,e,i,s,r,a,o,c,l,h,d,u,m,v,M,p){const f=this.elements;return f[0]=t,f[4]=e,f[8]=i,f[12]=s,f[1]=r,f[5]=a,f[9]=o,f[13]=c,f[2]=l,f[6]=h,f[10]=d,f[14]=u,f[3]=m,f[7]=v,f[11]=M,f[15]=p,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new Le().fromArray(this.elements)}copy(t){const e=this.elements,i=t.elements;return e[0]=i[0],e[1]=i[1],e[2]=i[2],e[3]=i[3],e[4]=i[4],e[5]=i[5],e[6]=i[6],e[7]=i[7],e[8]=i[8],e[9]=i[9],e[10]=i[10],e[11]=i[11],e[12]=i[12],e[13]=i[13],e[14]=i[14],e[15]=i[15],this}copyPosition(t){const e=this.elements,i=t.elements;return e[12]=i[12],e[13]=i[13],e[14]=i[14],this}setFromMatrix3(t){const e=t.elements;return this.set(e[0],e[3],e[6],0,e[1],e[4],e[7],0,e[2],e[5],e[8],0,0,0,0,1),this}extractBasis(t,e,i){return this.determinantAffine()===0?(t.set(1,0,0),e.set(0,1,0),i.set(0,0,1),this):(t.setFromMatrixColumn(this,0),e.setFromMatrixColumn(this,1),i.setFromMatrixColumn(this,2),this)}makeBasis(t,e,i){return this.set(t.x,e.x,i.x,0,t.y,e.y,i.y,0,t.z,e.z,i.z,0,0,0,0,1),this}extractRotation(t){if(t.determinantAffine()===0)return this.identity();const e=this.elements,i=t.elements,s=1/ar.setFromMatrixColumn(t,0).length(),r=1/ar.setFromMatrixColumn(t,1).length(),a=1/ar.setFromMatrixColumn(t,2).length();return e[0]=i[0]*s,e[1]=i[1]*s,e[2]=i[2]*s,e[3]=0,e[4]=i[4]*r,e[5]=i[5]*r,e[6]=i[6]*r,e[7]=0,e[8]=i[8]*a,e[9]=i[9]*a,e[10]=i[10]*a,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromEuler(t){const e=this.elements,i=t.x,s=t.y,r=t.z,a=Math.cos(i),o=Math.sin(i),c=Math.cos(s),l=Math.sin(s),h=Math.cos(r),d=Math.sin(r);if(t.order==="XYZ"){const u=a*h,m=a*d,v=o*h,M=o*d;e[0]=c*h,e[4]=-c*d,e[8]=l,e[1]=m+v*l,e[5]=u-M*l,e[9]=-o*c,e[2]=M-u*l,e[6]=v+m*l,e[10]=a*c}else if(t.order==="YXZ"){const u=c*h,m=c*d,v=l*h,M=l*d;e[0]=u+M*o,e[4]=v*o-m,e[8]=a*l,e[1]=a*d,e[5]=a*h,e[9]=-o,e[2]=m*o-v,e[6]=M+u*o,e[10]=a*c}else if(t.order==="ZXY"){const u=c*h,m=c*d,v=l*h,M=l*d;e[0]=u-M*o,e[4]=-a*d,e[8]=v+m*o,e[1]=m+v*o,e[5]=a*h,e[9]=M-u*o,e[2]=-a*l,e[6]=o,e[10]=a*c}else if(t.order==="ZYX"){const u=a*h,m=a*d,v=o*h,M=o*d;e[0]=c*h,e[4]=v*l-m,e[8]=u*l+M,e[1]=c*d,e[5]=M*l+u,e[9]=m*l-v,e[2]=-l,e[6]=o*c,e[10]=a*c}else if(t.order==="YZX"){const u=a*c,m=a*l,v=o*c,M=o*l;e[0]=c*h,e[4]=M-u*d,e[8]=v*d+m,e[1]=d,e[5]=a*h,e[9]=-o*h,e[2]=-l*h,e[6]=m*d+v,e[10]=u-M*d}else if(t.order==="XZY"){const u=a*c,m=a*l,v=o*c,M=o*l;e[0]=c*h,e[4]=-d,e[8]=l*h,e[1]=u*d+M,e[5]=a*h,e[9]=m*d-v,e[2]=v*d-m,e[6]=o*h,e[10]=M*d+u}return e[3]=0,e[7]=0,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromQuaternion(t){return this.compose(qg,t,Kg)}lookAt(t,e,i){const s=this.elements;return qn.subVectors(t,e),qn.lengthSq()===0&&(qn.z=1),qn.normalize(),ds.crossVectors(i,qn),ds.lengthSq()===0&&(Math.abs(i.z)===1?qn.x+=1e-4:qn.z+=1e-4,qn.normalize(),ds.crossVectors(i,qn)),ds.normalize(),Ua.crossVectors(qn,ds),s[0]=ds.x,s[4]=Ua.x,s[8]=qn.x,s[1]=ds.y,s[5]=Ua.y,s[9]=qn.y,s[2]=ds.z,s[6]=Ua.z,s[10]=qn.z,this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){const i=t.elements,s=e.elements,r=this.elements,a=i[0],o=i[4],c=i[8],l=i[12],h=i[1],d=i[5],u=i[9],m=i[13],v=i[2],M=i[6],p=i[10],f=i[14],x=i[3],A=i[7],y=i[11],R=i[15],E=s[0],g=s[4],T=s[8],z=s[12],U=s[1],D=s[5],I=s[9],B=s[13],L=s[2],G=s[6],Y=s[10],k=s[14],lt=s[3],K=s[7],Q=s[11],nt=s[15];return r[0]=a*E+o*U+c*L+l*lt,r[4]=a*g+o*D+c*G+l*K,r[8]=a*T+o*I+c*Y+l*Q,r[12]=a*z+o*B+c*k+l*nt,r[1]=h*E+d*U+u*L+m*lt,r[5]=h*g+d*D+u*G+m*K,r[9]=h*T+d*I+u*Y+m*Q,r[13]=h*z+d*B+u*k+m*nt,r[2]=v*E+M*U+p*L+f*lt,r[6]=v*g+M*D+p*G+f*K,r[10]=v*T+M*I+p*Y+f*Q,r[14]=v*z+M*B+p*k+f*nt,r[3]=x*E+A*U+y*L+R*lt,r[7]=x*g+A*D+y*G+R*K,r[11]=x*T+A*I+y*Y+R*Q,r[15]=x*z+A*B+y*k+R*nt,this}multiplyScalar(t){const e=this.elements;return e[0]*=t,e[4]*=t,e[8]*=t,e[12]*=t,e[1]*=t,e[5]*=t,e[9]*=t,e[13]*=t,e[2]*=t,e[6]*=t,e[10]*=t,e[14]*=t,e[3]*=t,e[7]*=t,e[11]*=t,e[15]*=t,this}determinant(){const t=this.elements,e=t[0],i=t[4],s=t[8],r=t[12],a=t[1],o=t[5],c=t[9],l=t[13],h=t[2],d=t[6],u=t[10],m=t[14],v=t[3],M=t[7],p=t[11],f=t[15],x=c*m-l*u,A=o*m-l*d,y=o*u-c*d,R=a*m-l*h,E=a*u-c*h,g=a*d-o*h;return e*(M*x-p*A+f*y)-i*(v*x-p*R+f*E)+s*(v*A-M*R+f*g)-r*(v*y-M*E+p*g)}determinantAffine(){const t=this.elements,e=t[0],i=t[4],s=t[8],r=t[1],a=t[5],o=t[9],c=t[2],l=t[6],h=t[10];return e*(a*h-o*l)-i*(r*h-o*c)+s*(r*l-a*c)}transpose(){const t=this.elements;let e;return e=t[1],t[1]=t[4],t[4]=e,e=t[2],t[2]=t[8],t[8]=e,e=t[6],t[6]=t[9],t[9]=e,e=t[3],t[3]=t[12],t[12]=e,e=t[7],t[7]=t[13],t[13]=e,e=t[11],t[11]=t[14],t[14]=e,this}setPosition(t,e,i){const s=this.elements;return t.isVector3?(s[12]=t.x,s[13]=t.y,s[14]=t.z):(s[12]=t,s[13]=e,s[14]=i),this}invert(){const t=this.elements,e=t[0],i=t[1],s=t[2],r=t[3],a=t[4],o=t[5],c=t[6],l=t[7],h=t[8],d=t[9],u=t[10],m=t[11],v=t[12],M=t[13],p=t[14],f=t[15],x=e*o-i*a,A=e*c-s*a,y=e*l-r*a,R=i*c-s*o,E=i*l-r*o,g=s*l-r*c,T=h*M-d*v,z=h*p-u*v,U=h*f-m*v,D=d*p-u*M,I=d*f-m*M,B=u*f-m*p,L=x*B-A*I+y*D+R*U-E*z+g*T;if(L===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);const G=1/L;return t[0]=(o*B-c*I+l*D)*G,t[1]=(s*I-i*B-r*D)*G,t[2]=(M*g-p*E+f*R)*G,t[3]=(u*E-d*g-m*R)*G,t[4]=(c*U-a*B-l*z)*G,t[5]=(e*B-s*U+r*z)*G,t[6]=(p*y-v*g-f*A)*G,t[7]=(h*g-u*y+m*A)*G,t[8]=(a*I-o*U+l*T)*G,t[9]=(i*U-e*I-r*T)*G,t[10]=(v*E-M*y+f*x)*G,t[11]=(d*y-h*E-m*x)*G,t[12]=(o*z-a*D-c*T)*G,t[13]=(e*D-i*z+s*T)*G,t[14]=(M*A-v*R-p*x)*G,t[15]=(h*R-d*A+u*x)*G,this}scale(t){const e=this.elements,i=t.x,s=t.y,r=t.z;return e[0]*=i,e[4]*=s,e[8]*=r,e[1]*=i,e[5]*=s,e[9]*=r,e[2]*=i,e[6]*=s,e[10]*=r,e[3]*=i,e[7]*=s,e[11]*=r,this}getMaxScaleOnAxis(){const t=this.elements,e=t[0]*t[0]+t[1]*t[1]+t[2]*t[2],i=t[4]*t[4]+t[5]*t[5]+t[6]*t[6],s=t[8]*t[8]+t[9]*t[9]+t[10]*t[10];return Math.sqrt(Math.max(e,i,s))}makeTranslation(t,e,i){return t.isVector3?this.set(1,0,0,t.x,0,1,0,t.y,0,0,1,t.z,0,0,0,1):this.set(1,0,0,t,0,1,0,e,0,0,1,i,0,0,0,1),this}makeRotationX(t){const e=Math.cos(t),i=Math.sin(t);return this.set(1,0,0,0,0,e,-i,0,0,i,e,0,0,0,0,1),this}makeRotationY(t){const e=Math.cos(t),i=Math.sin(t);return this.set(e,0,i,0,0,1,0,0,-i,0,e,0,0,0,0,1),this}makeRotationZ(t){const e=Math.cos(t),i=Math.sin(t);return this.set(e,-i,0,0,i,e,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(t,e){const i=Math.cos(e),s=Math.sin(e),r=1-i,a=t.x,o=t.y,c=t.z,l=r*a,h=r*o;return this.set(l*a+i,l*o-s*c,l*c+s*o,0,l*o+s*c,h*o+i,h*c-s*a,0,l*c-s*o,h*c+s*a,r*c*c+i,0,0,0,0,1),this}makeScale(t,e,i){return this.set(t,0,0,0,0,e,0,0,0,0,i,0,0,0,0,1),this}makeShear(t,e,i,s,r,a){return this.set(1,i,r,0,t,1,a,0,e,s,1,0,0,0,0,1),this}compose(t,e,i){const s=this.elements,r=e._x,a=e._y,o=e._z,c=e._w,l=r+r,h=a+a,d=o+o,u=r*l,m=r*h,v=r*d,M=a*h,p=a*d,f=o*d,x=c*l,A=c*h,y=c*d,R=i.x,E=i.y,g=i.z;return s[0]=(1-(M+f))*R,s[1]=(m+y)*R,s[2]=(v-A)*R,s[3]=0,s[4]=(m-y)*E,s[5]=(1-(u+f))*E,s[6]=(p+x)*E,s[7]=0,s[8]=(v+A)*g,s[9]=(p-x)*g,s[10]=(1-(u+M))*g,s[11]=0,s[12]=t.x,s[13]=t.y,s[14]=t.z,s[15]=1,this}decompose(t,e,i){const s=this.elements;t.x=s[12],t.y=s[13],t.z=s[14];const r=this.determinantAffine();if(r===0)return i.set(1,1,1),e.identity(),this;let a=ar.set(s[0],s[1],s[2]).length();const o=ar.set(s[4],s[5],s[6]).length(),c=ar.set(s[8],s[9],s[10]).length();r<0&&(a=-a),pi.copy(this);const l=1/a,h=1/o,d=1/c;return pi.elements[0]*=l,pi.elements[1]*=l,pi.elements[2]*=l,pi.elements[4]*=h,pi.elements[5]*=h,pi.elements[6]*=h,pi.elements[8]*=d,pi.elements[9]*=d,pi.elements[10]*=d,e.setFromRotationMatrix(pi),i.x=a,i.y=o,i.z=c,this}makePerspective(t,e,i,s,r,a,o=bi,c=!1){const l=this.elements,h=2*r/(e-t),d=2*r/(i-s),u=(e+t)/(e-t),m=(i+s)/(i-s);let v,M;if(c)v=r/(a-r),M=a*r/(a-r);else if(o===bi)v=-(a+r)/(a-r),M=-2*a*r/(a-r);else if(o===xa)v=-a/(a-r),M=-a*r/(a-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return l[0]=h,l[4]=0,l[8]=u,l[12]=0,l[1]=0,l[5]=d,l[9]=m,l[13]=0,l[2]=0,l[6]=0,l[10]=v,l[14]=M,l[3]=0,l[7]=0,l[11]=-1,l[15]=0,this}makeOrthographic(t,e,i,s,r,a,o=bi,c=!1){const l=this.elements,h=2/(e-t),d=2/(i-s),u=-(e+t)/(e-t),m=-(i+s)/(i-s);let v,M;if(c)v=1/(a-r),M=a/(a-r);else if(o===bi)v=-2/(a-r),M=-(a+r)/(a-r);else if(o===xa)v=-1/(a-r),M=-r/(a-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return l[0]=h,l[4]=0,l[8]=0,l[12]=u,l[1]=0,l[5]=d,l[9]=0,l[13]=m,l[2]=0,l[6]=0,l[10]=v,l[14]=M,l[3]=0,l[7]=0,l[11]=0,l[15]=1,this}equals(t){const e=this.elements,i=t.elements;for(let s=0;s<16;s++)if(e[s]!==i[s])return!1;return!0}fromArray(t,e=0){for(let i=0;i<16;i++)this.elements[i]=t[i+e];return this}toArray(t=[],e=0){const i=this.elements;return t[e]=i[0],t[e+1]=i[1],t[e+2]=i[2],t[e+3]=i[3],t[e+4]=i[4],t[e+5]=i[5],t[e+6]=i[6],t[e+7]=i[7],t[e+8]=i[8],t[e+9]=i[9],t[e+10]=i[10],t[e+11]=i[11],t[e+12]=i[12],t[e+13]=i[13],t[e+14]=i[14],t[e+15]=i[15],t}}const ar=new V,pi=new Le,qg=new V(0,0,0),Kg=new V(1,1,1),ds=new V,Ua=new V,qn=new V,Mu=new Le,yu=new rs;class ws{constructor(t=0,e=0,i=0,s=ws.DEFAULT_ORDER){this.isEuler=!0,this._x=t,this._y=e,this._z=i,this._order=s}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get order(){return this._order}set order(t){this._order=t,this._onChangeCallback()}set(t,e,i,s=this._order){return this._x=t,this._y=e,this._z=i,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(t){return this._x=t._x,this._y=t._y,this._z=t._z,this._order=t._order,this._onChangeCallback(),this}setFromRotationMatrix(t,e=this._order,i=!0){const s=t.elements,r=s[0],a=s[4],o=s[8],c=s[1],l=s[5],h=s[9],d=s[2],u=s[6],m=s[10];switch(e){case"XYZ":this._y=Math.asin(de(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-h,m),this._z=Math.atan2(-a,r)):(this._x=Math.atan2(u,l),this._z=0);break;case"YXZ":this._x=Math.asin(-de(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(o,m),this._z=Math.atan2(c,l)):(this._y=Math.atan2(-d,r),this._z=0);break;case"ZXY":this._x=Math.asin(de(u,-1,1)),Math.abs(u)<.9999999?(this._y=Math.atan2(-d,m),this._z=Math.atan2(-a,l)):(this._y=0,this._z=Math.atan2(c,r));break;case"ZYX":this._y=Math.asin(-de(d,-1,1)),Math.abs(d)<.9999999?(this._x=Math.atan2(u,m),this._z=Math.atan2(c,r)):(this._x=0,this._z=Math.atan2(-a,l));break;case"YZX":this._z=Math.asin(de(c,-1,1)),Math.abs(c)<.9999999?(this._x=Math.atan2(-h,l),this._y=Math.atan2(-d,r)):(this._x=0,this._y=Math.atan2(o,m));break;case"XZY":this._z=Math.asin(-de(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(u,l),this._y=Math.atan2(o,r)):(this._x=Math.atan2(-h,m),this._y=0);break;default:Kt("Euler: .setFromRotationMatrix() encountered an unknown order: "+e)}return this._order=e,i===!0&&this._onChangeCallback(),this}setFromQuaternion(t,e,i){return Mu.makeRotationFromQuaternion(t),this.setFromRotationMatrix(Mu,e,i)}setFromVector3(t,e=this._order){return this.set(t.x,t.y,t.z,e)}reorder(t){return yu.setFromEuler(this),this.setFromQuaternion(yu,t)}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._order===this._order}fromArray(t){return this._x=t[0],this._y=t[1],this._z=t[2],t[3]!==void 0&&(this._order=t[3]),this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._order,t}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}}ws.DEFAULT_ORDER="XYZ";class Eh{constructor(){this.mask=1}set(t){this.mask=(1<<t|0)>>>0}enable(t){this.mask|=1<<t|0}enableAll(){this.mask=-1}toggle(t){this.mask^=1<<t|0}disable(t){this.mask&=~(1<<t|0)}disableAll(){this.mask=0}test(t){return(this.mask&t.mask)!==0}isEnabled(t){return(this.mask&(1<<t|0))!==0}}let Zg=0;const Eu=new V,or=new rs,Yi=new Le,Fa=new V,Yr=new V,Jg=new V,Qg=new rs,bu=new V(1,0,0),wu=new V(0,1,0),Tu=new V(0,0,1),Au={type:"added"},jg={type:"removed"},lr={type:"childadded",child:null},_l={type:"childremoved",child:null};class Tn extends Cs{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:Zg++}),this.uuid=ba(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=Tn.DEFAULT_UP.clone();const t=new V,e=new ws,i=new rs,s=new V(1,1,1);function r(){i.setFromEuler(e,!1)}function a(){e.setFromQuaternion(i,void 0,!1)}e._onChange(r),i._onChange(a),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:t},rotation:{configurable:!0,enumerable:!0,value:e},quaternion:{configurable:!0,enumerable:!0,value:i},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new Le},normalMatrix:{value:new te}}),this.matrix=new Le,this.matrixWorld=new Le,this.matrixAutoUpdate=Tn.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=Tn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Eh,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(t){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(t),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(t){return this.quaternion.premultiply(t),this}setRotationFromAxisAngle(t,e){this.quaternion.setFromAxisAngle(t,e)}setRotationFromEuler(t){this.quaternion.setFromEuler(t,!0)}setRotationFromMatrix(t){this.quaternion.setFromRotationMatrix(t)}setRotationFromQuaternion(t){this.quaternion.copy(t)}rotateOnAxis(t,e){return or.setFromAxisAngle(t,e),this.quaternion.multiply(or),this}rotateOnWorldAxis(t,e){return or.setFromAxisAngle(t,e),this.quaternion.premultiply(or),this}rotateX(t){return this.rotateOnAxis(bu,t)}rotateY(t){return this.rotateOnAxis(wu,t)}rotateZ(t){return this.rotateOnAxis(Tu,t)}translateOnAxis(t,e){return Eu.copy(t).applyQuaternion(this.quaternion),this.position.add(Eu.multiplyScalar(e)),this}translateX(t){return this.translateOnAxis(bu,t)}translateY(t){return this.translateOnAxis(wu,t)}translateZ(t){return this.translateOnAxis(Tu,t)}localToWorld(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(this.matrixWorld)}worldToLocal(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(Yi.copy(this.matrixWorld).invert())}lookAt(t,e,i){t.isVector3?Fa.copy(t):Fa.set(t,e,i);const s=this.parent;this.updateWorldMatrix(!0,!1),Yr.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?Yi.lookAt(Yr,Fa,this.up):Yi.lookAt(Fa,Yr,this.up),this.quaternion.setFromRotationMatrix(Yi),s&&(Yi.extractRotation(s.matrixWorld),or.setFromRotationMatrix(Yi),this.quaternion.premultiply(or.invert()))}add(t){if(arguments.length>1){for(let e=0;e<arguments.length;e++)this.add(arguments[e]);return this}return t===this?(ve("Object3D.add: object can't be added as a child of itself.",t),this):(t&&t.isObject3D?(t.removeFromParent(),t.parent=this,this.children.push(t),t.dispatchEvent(Au),lr.child=t,this.dispatchEvent(lr),lr.child=null):ve("Object3D.add: object not an instance of THREE.Object3D.",t),this)}remove(t){if(arguments.length>1){for(let i=0;i<arguments.length;i++)this.remove(arguments[i]);return this}const e=this.children.indexOf(t);return e!==-1&&(t.parent=null,this.children.splice(e,1),t.dispatchEvent(jg),_l.child=t,this.dispatchEvent(_l),_l.child=null),this}removeFromParent(){const t=this.parent;return t!==null&&t.remove(this),this}clear(){return this.remove(...this.children)}attach(t){return this.updateWorldMatrix(!0,!1),Yi.copy(this.matrixWorld).invert(),t.parent!==null&&(t.parent.updateWorldMatrix(!0,!1),Yi.multiply(t.parent.matrixWorld)),t.applyMatrix4(Yi),t.removeFromParent(),t.parent=this,this.children.push(t),t.updateWorldMatrix(!1,!0),t.dispatchEvent(Au),lr.child=t,this.dispatchEvent(lr),lr.child=null,this}getObjectById(t){return this.getObjectByProperty("id",t)}getObjectByName(t){return this.getObjectByProperty("name",t)}getObjectByProperty(t,e){if(this[t]===e)return this;for(let i=0,s=this.children.length;i<s;i++){const a=this.children[i].getObjectByProperty(t,e);if(a!==void 0)return a}}getObjectsByProperty(t,e,i=[]){this[t]===e&&i.push(this);const s=this.children;for(let r=0,a=s.length;r<a;r++)s[r].getObjectsByProperty(t,e,i);return i}getWorldPosition(t){return this.updateWorldMatrix(!0,!1),t.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Yr,t,Jg),t}getWorldScale(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Yr,Qg,t),t}getWorldDirection(t){this.updateWorldMatrix(!0,!1);const e=this.matrixWorld.elements;return t.set(e[8],e[9],e[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(t){t(this);const e=this.children;for(let i=0,s=e.length;i<s;i++)e[i].traverse(t)}traverseVisible(t){if(this.visible===!1)return;t(this);const e=this.children;for(let i=0,s=e.length;i<s;i++)e[i].traverseVisible(t)}traverseAncestors(t){const e=this.parent;e!==null&&(t(e),e.traverseAncestors(t))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);const t=this.pivot;if(t!==null){const e=t.x,i=t.y,s=t.z,r=this.matrix.elements;r[12]+=e-r[0]*e-r[4]*i-r[8]*s,r[13]+=i-r[1]*e-r[5]*i-r[9]*s,r[14]+=s-r[2]*e-r[6]*i-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(t){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||t)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,t=!0);const e=this.children;for(let i=0,s=e.length;i<s;i++)e[i].updateMatrixWorld(t)}updateWorldMatrix(t,e,i=!1){const s=this.parent;if(t===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||i)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,i=!0),e===!0){const r=this.children;for(let a=0,o=r.length;a<o;a++)r[a].updateWorldMatrix(!1,!0,i)}}toJSON(t){const e=t===void 0||typeof t=="string",i={};e&&(t={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},i.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});const s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(o=>({...o,boundingBox:o.boundingBox?o.boundingBox.toJSON():void 0,boundingSphere:o.boundingSphere?o.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(o=>({...o})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(t),s.indirectTexture=this._indirectTexture.toJSON(t),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(t)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(o,c){return o[c.uuid]===void 0&&(o[c.uuid]=c.toJSON(t)),c.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(t).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(t).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(t.geometries,this.geometry);const o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){const c=o.shapes;if(Array.isArray(c))for(let l=0,h=c.length;l<h;l++){const d=c[l];r(t.shapes,d)}else r(t.shapes,c)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(t.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){const o=[];for(let c=0,l=this.material.length;c<l;c++)o.push(r(t.materials,this.material[c]));s.material=o}else s.material=r(t.materials,this.material);if(this.children.length>0){s.children=[];for(let o=0;o<this.children.length;o++)s.children.push(this.children[o].toJSON(t).object)}if(this.animations.length>0){s.animations=[];for(let o=0;o<this.animations.length;o++){const c=this.animations[o];s.animations.push(r(t.animations,c))}}if(e){const o=a(t.geometries),c=a(t.materials),l=a(t.textures),h=a(t.images),d=a(t.shapes),u=a(t.skeletons),m=a(t.animations),v=a(t.nodes);o.length>0&&(i.geometries=o),c.length>0&&(i.materials=c),l.length>0&&(i.textures=l),h.length>0&&(i.images=h),d.length>0&&(i.shapes=d),u.length>0&&(i.skeletons=u),m.length>0&&(i.animations=m),v.length>0&&(i.nodes=v)}return i.object=s,i;function a(o){const c=[];for(const l in o){const h=o[l];delete h.metadata,c.push(h)}return c}}clone(t){return new this.constructor().copy(this,t)}copy(t,e=!0){if(this.name=t.name,this.up.copy(t.up),this.position.copy(t.position),this.rotation.order=t.rotation.order,this.quaternion.copy(t.quaternion),this.scale.copy(t.scale),this.pivot=t.pivot!==null?t.pivot.clone():null,this.matrix.copy(t.matrix),this.matrixWorld.copy(t.matrixWorld),this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrixWorldAutoUpdate=t.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=t.matrixWorldNeedsUpdate,this.layers.mask=t.layers.mask,this.visible=t.visible,this.castShadow=t.castShadow,this.receiveShadow=t.receiveShadow,this.frustumCulled=t.frustumCulled,this.renderOrder=t.renderOrder,this.static=t.static,this.animations=t.animations.slice(),this.userData=JSON.parse(JSON.stringify(t.userData)),e===!0)for(let i=0;i<t.children.length;i++){const s=t.children[i];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}}Tn.DEFAULT_UP=new V(0,1,0);Tn.DEFAULT_MATRIX_AUTO_UPDATE=!0;Tn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;class Mr extends Tn{constructor(){super(),this.isGroup=!0,this.type="Group"}}const t_={type:"move"};class vl{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Mr,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Mr,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new V,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new V),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Mr,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new V,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new V,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(t){return this._targetRay!==null&&this._targetRay.dispatchEvent(t),this._grip!==null&&this._grip.dispatchEvent(t),this._hand!==null&&this._hand.dispatchEvent(t),this}connect(t){if(t&&t.hand){const e=this._hand;if(e)for(const i of t.hand.values())this._getHandJoint(e,i)}return this.dispatchEvent({type:"connected",data:t}),this}disconnect(t){return this.dispatchEvent({type:"disconnected",data:t}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(t,e,i){let s=null,r=null,a=null;const o=this._targetRay,c=this._grip,l=this._hand;if(t&&e.session.visibilityState!=="visible-blurred"){if(l&&t.hand){a=!0;for(const M of t.hand.values()){const p=e.getJointPose(M,i),f=this._getHandJoint(l,M);p!==null&&(f.matrix.fromArray(p.transform.matrix),f.matrix.decompose(f.position,f.quaternion,f.scale),f.matrixWorldNeedsUpdate=!0,f.jointRadius=p.radius),f.visible=p!==null}const h=l.joints["index-finger-tip"],d=l.joints["thumb-tip"],u=h.position.distanceTo(d.position),m=.02,v=.005;l.inputState.pinching&&u>m+v?(l.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:t.handedness,target:this})):!l.inputState.pinching&&u<=m-v&&(l.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:t.handedness,target:this}))}else c!==null&&t.gripSpace&&(r=e.getPose(t.gripSpace,i),r!==null&&(c.matrix.fromArray(r.transform.matrix),c.matrix.decompose(c.position,c.quaternion,c.scale),c.matrixWorldNeedsUpdate=!0,r.linearVelocity?(c.hasLinearVelocity=!0,c.linearVelocity.copy(r.linearVelocity)):c.hasLinearVelocity=!1,r.angularVelocity?(c.hasAngularVelocity=!0,c.angularVelocity.copy(r.angularVelocity)):c.hasAngularVelocity=!1,c.eventsEnabled&&c.dispatchEvent({type:"gripUpdated",data:t,target:this})));o!==null&&(s=e.getPose(t.targetRaySpace,i),s===null&&r!==null&&(s=r),s!==null&&(o.matrix.fromArray(s.transform.matrix),o.matrix.decompose(o.position,o.quaternion,o.scale),o.matrixWorldNeedsUpdate=!0,s.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(s.linearVelocity)):o.hasLinearVelocity=!1,s.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(s.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(t_)))}return o!==null&&(o.visible=s!==null),c!==null&&(c.visible=r!==null),l!==null&&(l.visible=a!==null),this}_getHandJoint(t,e){if(t.joints[e.jointName]===void 0){const i=new Mr;i.matrixAutoUpdate=!1,i.visible=!1,t.joints[e.jointName]=i,t.add(i)}return t.joints[e.jointName]}}const qf={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},fs={h:0,s:0,l:0},Oa={h:0,s:0,l:0};function xl(n,t,e){return e<0&&(e+=1),e>1&&(e-=1),e<1/6?n+(t-n)*6*e:e<1/2?t:e<2/3?n+(t-n)*6*(2/3-e):n}class le{constructor(t,e,i){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(t,e,i)}set(t,e,i){if(e===void 0&&i===void 0){const s=t;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(t,e,i);return this}setScalar(t){return this.r=t,this.g=t,this.b=t,this}setHex(t,e=ai){return t=Math.floor(t),this.r=(t>>16&255)/255,this.g=(t>>8&255)/255,this.b=(t&255)/255,me.colorSpaceToWorking(this,e),this}setRGB(t,e,i,s=me.workingColorSpace){return this.r=t,this.g=e,this.b=i,me.colorSpaceToWorking(this,s),this}setHSL(t,e,i,s=me.workingColorSpace){if(t=Bg(t,1),e=de(e,0,1),i=de(i,0,1),e===0)this.r=this.g=this.b=i;else{const r=i<=.5?i*(1+e):i+e-i*e,a=2*i-r;this.r=xl(a,r,t+1/3),this.g=xl(a,r,t),this.b=xl(a,r,t-1/3)}return me.colorSpaceToWorking(this,s),this}setStyle(t,e=ai){function i(r){r!==void 0&&parseFloat(r)<1&&Kt("Color: Alpha component of "+t+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(t)){let r;const a=s[1],o=s[2];switch(a){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return i(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,e);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return i(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,e);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return i(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,e);break;default:Kt("Color: Unknown color model "+t)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(t)){const r=s[1],a=r.length;if(a===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,e);if(a===6)return this.setHex(parseInt(r,16),e);Kt("Color: Invalid hex color "+t)}else if(t&&t.length>0)return this.setColorName(t,e);return this}setColorName(t,e=ai){const i=qf[t.toLowerCase()];return i!==void 0?this.setHex(i,e):Kt("Color: Unknown color "+t),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(t){return this.r=t.r,this.g=t.g,this.b=t.b,this}copySRGBToLinear(t){return this.r=es(t.r),this.g=es(t.g),this.b=es(t.b),this}copyLinearToSRGB(t){return this.r=br(t.r),this.g=br(t.g),this.b=br(t.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(t=ai){return me.workingToColorSpace(Pn.copy(this),t),Math.round(de(Pn.r*255,0,255))*65536+Math.round(de(Pn.g*255,0,255))*256+Math.round(de(Pn.b*255,0,255))}getHexString(t=ai){return("000000"+this.getHex(t).toString(16)).slice(-6)}getHSL(t,e=me.workingColorSpace){me.workingToColorSpace(Pn.copy(this),e);const i=Pn.r,s=Pn.g,r=Pn.b,a=Math.max(i,s,r),o=Math.min(i,s,r);let c,l;const h=(o+a)/2;if(o===a)c=0,l=0;else{const d=a-o;switch(l=h<=.5?d/(a+o):d/(2-a-o),a){case i:c=(s-r)/d+(s<r?6:0);break;case s:c=(r-i)/d+2;break;case r:c=(i-s)/d+4;break}c/=6}return t.h=c,t.s=l,t.l=h,t}getRGB(t,e=me.workingColorSpace){return me.workingToColorSpace(Pn.copy(this),e),t.r=Pn.r,t.g=Pn.g,t.b=Pn.b,t}getStyle(t=ai){me.workingToColorSpace(Pn.copy(this),t);const e=Pn.r,i=Pn.g,s=Pn.b;return t!==ai?`color(${t} ${e.toFixed(3)} ${i.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(e*255)},${Math.round(i*255)},${Math.round(s*255)})`}offsetHSL(t,e,i){return this.getHSL(fs),this.setHSL(fs.h+t,fs.s+e,fs.l+i)}add(t){return this.r+=t.r,this.g+=t.g,this.b+=t.b,this}addColors(t,e){return this.r=t.r+e.r,this.g=t.g+e.g,this.b=t.b+e.b,this}addScalar(t){return this.r+=t,this.g+=t,this.b+=t,this}sub(t){return this.r=Math.max(0,this.r-t.r),this.g=Math.max(0,this.g-t.g),this.b=Math.max(0,this.b-t.b),this}multiply(t){return this.r*=t.r,this.g*=t.g,this.b*=t.b,this}multiplyScalar(t){return this.r*=t,this.g*=t,this.b*=t,this}lerp(t,e){return this.r+=(t.r-this.r)*e,this.g+=(t.g-this.g)*e,this.b+=(t.b-this.b)*e,this}lerpColors(t,e,i){return this.r=t.r+(e.r-t.r)*i,this.g=t.g+(e.g-t.g)*i,this.b=t.b+(e.b-t.b)*i,this}lerpHSL(t,e){this.getHSL(fs),t.getHSL(Oa);const i=dl(fs.h,Oa.h,e),s=dl(fs.s,Oa.s,e),r=dl(fs.l,Oa.l,e);return this.setHSL(i,s,r),this}setFromVector3(t){return this.r=t.x,this.g=t.y,this.b=t.z,this}applyMatrix3(t){const e=this.r,i=this.g,s=this.b,r=t.elements;return this.r=r[0]*e+r[3]*i+r[6]*s,this.g=r[1]*e+r[4]*i+r[7]*s,this.b=r[2]*e+r[5]*i+r[8]*s,this}equals(t){return t.r===this.r&&t.g===this.g&&t.b===this.b}fromArray(t,e=0){return this.r=t[e],this.g=t[e+1],this.b=t[e+2],this}toArray(t=[],e=0){return t[e]=this.r,t[e+1]=this.g,t[e+2]=this.b,t}fromBufferAttribute(t,e){return this.r=t.getX(e),this.g=t.getY(e),this.b=t.getZ(e),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}}const Pn=new le;le.NAMES=qf;class Kf extends Tn{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new ws,this.environmentIntensity=1,this.environmentRotation=new ws,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(t,e){return super.copy(t,e),this.background=t.background!==null?t.background.clone():null,this.environment=t.environment!==null?t.environment.clone():null,this.fog=t.fog!==null?t.fog.clone():null,this.backgroundBlurriness=t.backgroundBlurriness,this.backgroundIntensity=t.backgroundIntensity,this.backgroundRotation.copy(t.backgroundRotation),this.environmentIntensity=t.environmentIntensity,this.environmentRotation.copy(t.environmentRotation),this.overrideMaterial=t.overrideMaterial!==null?t.overrideMaterial.clone():null,this.matrixAutoUpdate=t.matrixAutoUpdate,this}toJSON(t){const e=super.toJSON(t);return this.fog!==null&&(e.object.fog=this.fog.toJSON()),e.object.backgroundBlurriness=this.backgroundBlurriness,e.object.backgroundIntensity=this.backgroundIntensity,e.object.backgroundRotation=this.backgroundRotation.toArray(),e.object.environmentIntensity=this.environmentIntensity,e.object.environmentRotation=this.environmentRotation.toArray(),e}}const mi=new V,qi=new V,Sl=new V,Ki=new V,cr=new V,hr=new V,Ru=new V,Ml=new V,yl=new V,El=new V,bl=new Qe,wl=new Qe,Tl=new Qe;class Mi{constructor(t=new V,e=new V,i=new V){this.a=t,this.b=e,this.c=i}static getNormal(t,e,i,s){s.subVectors(i,e),mi.subVectors(t,e),s.cross(mi);const r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(t,e,i,s,r){mi.subVectors(s,e),qi.subVectors(i,e),Sl.subVectors(t,e);const a=mi.dot(mi),o=mi.dot(qi),c=mi.dot(Sl),l=qi.dot(qi),h=qi.dot(Sl),d=a*l-o*o;if(d===0)return r.set(0,0,0),null;const u=1/d,m=(l*c-o*h)*u,v=(a*h-o*c)*u;return r.set(1-m-v,v,m)}static containsPoint(t,e,i,s){return this.getBarycoord(t,e,i,s,Ki)===null?!1:Ki.x>=0&&Ki.y>=0&&Ki.x+Ki.y<=1}static getInterpolation(t,e,i,s,r,a,o,c){return this.getBarycoord(t,e,i,s,Ki)===null?(c.x=0,c.y=0,"z"in c&&(c.z=0),"w"in c&&(c.w=0),null):(c.setScalar(0),c.addScaledVector(r,Ki.x),c.addScaledVector(a,Ki.y),c.addScaledVector(o,Ki.z),c)}static getInterpolatedAttribute(t,e,i,s,r,a){return bl.setScalar(0),wl.setScalar(0),Tl.setScalar(0),bl.fromBufferAttribute(t,e),wl.fromBufferAttribute(t,i),Tl.fromBufferAttribute(t,s),a.setScalar(0),a.addScaledVector(bl,r.x),a.addScaledVector(wl,r.y),a.addScaledVector(Tl,r.z),a}static isFrontFacing(t,e,i,s){return mi.subVectors(i,e),qi.subVectors(t,e),mi.cross(qi).dot(s)<0}set(t,e,i){return this.a.copy(t),this.b.copy(e),this.c.copy(i),this}setFromPointsAndIndices(t,e,i,s){return this.a.copy(t[e]),this.b.copy(t[i]),this.c.copy(t[s]),this}setFromAttributeAndIndices(t,e,i,s){return this.a.fromBufferAttribute(t,e),this.b.fromBufferAttribute(t,i),this.c.fromBufferAttribute(t,s),this}clone(){return new this.constructor().copy(this)}copy(t){return this.a.copy(t.a),this.b.copy(t.b),this.c.copy(t.c),this}getArea(){return mi.subVectors(this.c,this.b),qi.subVectors(this.a,this.b),mi.cross(qi).length()*.5}getMidpoint(t){return t.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(t){return Mi.getNormal(this.a,this.b,this.c,t)}getPlane(t){return t.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(t,e){return Mi.getBarycoord(t,this.a,this.b,this.c,e)}getInterpolation(t,e,i,s,r){return Mi.getInterpolation(t,this.a,this.b,this.c,e,i,s,r)}containsPoint(t){return Mi.containsPoint(t,this.a,this.b,this.c)}isFrontFacing(t){return Mi.isFrontFacing(this.a,this.b,this.c,t)}intersectsBox(t){return t.intersectsTriangle(this)}closestPointToPoint(t,e){const i=this.a,s=this.b,r=this.c;let a,o;cr.subVectors(s,i),hr.subVectors(r,i),Ml.subVectors(t,i);const c=cr.dot(Ml),l=hr.dot(Ml);if(c<=0&&l<=0)return e.copy(i);yl.subVectors(t,s);const h=cr.dot(yl),d=hr.dot(yl);if(h>=0&&d<=h)return e.copy(s);const u=c*d-h*l;if(u<=0&&c>=0&&h<=0&&c-h>0)return a=c/(c-h),e.copy(i).addScaledVector(cr,a);El.subVectors(t,r);const m=cr.dot(El),v=hr.dot(El);if(v>=0&&m<=v)return e.copy(r);const M=m*l-c*v;if(M<=0&&l>=0&&v<=0)return o=l/(l-v),e.copy(i).addScaledVector(hr,o);const p=h*v-m*d;if(p<=0&&d-h>=0&&m-v>=0)return Ru.subVectors(r,s),o=(d-h)/(d-h+(m-v)),e.copy(s).addScaledVector(Ru,o);const f=1/(p+M+u);return a=M*f,o=u*f,e.copy(i).addScaledVector(cr,a).addScaledVector(hr,o)}equals(t){return t.a.equals(this.a)&&t.b.equals(this.b)&&t.c.equals(this.c)}}class wa{constructor(t=new V(1/0,1/0,1/0),e=new V(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=t,this.max=e}set(t,e){return this.min.copy(t),this.max.copy(e),this}setFromArray(t){this.makeEmpty();for(let e=0,i=t.length;e<i;e+=3)this.expandByPoint(gi.fromArray(t,e));return this}setFromBufferAttribute(t){this.makeEmpty();for(let e=0,i=t.count;e<i;e++)this.expandByPoint(gi.fromBufferAttribute(t,e));return this}setFromPoints(t){this.makeEmpty();for(let e=0,i=t.length;e<i;e++)this.expandByPoint(t[e]);return this}setFromCenterAndSize(t,e){const i=gi.copy(e).multiplyScalar(.5);return this.min.copy(t).sub(i),this.max.copy(t).add(i),this}setFromObject(t,e=!1){return this.makeEmpty(),this.expandByObject(t,e)}clone(){return new this.constructor().copy(this)}copy(t){return this.min.copy(t.min),this.max.copy(t.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(t){return this.isEmpty()?t.set(0,0,0):t.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(t){return this.isEmpty()?t.set(0,0,0):t.subVectors(this.max,this.min)}expandByPoint(t){return this.min.min(t),this.max.max(t),this}expandByVector(t){return this.min.sub(t),this.max.add(t),this}expandByScalar(t){return this.min.addScalar(-t),this.max.addScalar(t),this}expandByObject(t,e=!1){t.updateWorldMatrix(!1,!1);const i=t.geometry;if(i!==void 0){const r=i.getAttribute("position");if(e===!0&&r!==void 0&&t.isInstancedMesh!==!0&&t.isBatchedMesh!==!0)for(let a=0,o=r.count;a<o;a++)t.isMesh===!0?t.getVertexPosition(a,gi):gi.fromBufferAttribute(r,a),gi.applyMatrix4(t.matrixWorld),this.expandByPoint(gi);else t.boundingBox!==void 0?(t.boundingBox===null&&t.computeBoundingBox(),Ba.copy(t.boundingBox)):(i.boundingBox===null&&i.computeBoundingBox(),Ba.copy(i.boundingBox)),Ba.applyMatrix4(t.matrixWorld),this.union(Ba)}const s=t.children;for(let r=0,a=s.length;r<a;r++)this.expandByObject(s[r],e);return this}containsPoint(t){return t.x>=this.min.x&&t.x<=this.max.x&&t.y>=this.min.y&&t.y<=this.max.y&&t.z>=this.min.z&&t.z<=this.max.z}containsBox(t){return this.min.x<=t.min.x&&t.max.x<=this.max.x&&this.min.y<=t.min.y&&t.max.y<=this.max.y&&this.min.z<=t.min.z&&t.max.z<=this.max.z}getParameter(t,e){return e.set((t.x-this.min.x)/(this.max.x-this.min.x),(t.y-this.min.y)/(this.max.y-this.min.y),(t.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(t){return t.max.x>=this.min.x&&t.min.x<=this.max.x&&t.max.y>=this.min.y&&t.min.y<=this.max.y&&t.max.z>=this.min.z&&t.min.z<=this.max.z}intersectsSphere(t){return this.clampPoint(t.center,gi),gi.distanceToSquared(t.center)<=t.radius*t.radius}intersectsPlane(t){let e,i;return t.normal.x>0?(e=t.normal.x*this.min.x,i=t.normal.x*this.max.x):(e=t.normal.x*this.max.x,i=t.normal.x*this.min.x),t.normal.y>0?(e+=t.normal.y*this.min.y,i+=t.normal.y*this.max.y):(e+=t.normal.y*this.max.y,i+=t.normal.y*this.min.y),t.normal.z>0?(e+=t.normal.z*this.min.z,i+=t.normal.z*this.max.z):(e+=t.normal.z*this.max.z,i+=t.normal.z*this.min.z),e<=-t.constant&&i>=-t.constant}intersectsTriangle(t){if(this.isEmpty())return!1;this.getCenter(qr),za.subVectors(this.max,qr),ur.subVectors(t.a,qr),dr.subVectors(t.b,qr),fr.subVectors(t.c,qr),ps.subVectors(dr,ur),ms.subVectors(fr,dr),Ns.subVectors(ur,fr);let e=[0,-ps.z,ps.y,0,-ms.z,ms.y,0,-Ns.z,Ns.y,ps.z,0,-ps.x,ms.z,0,-ms.x,Ns.z,0,-Ns.x,-ps.y,ps.x,0,-ms.y,ms.x,0,-Ns.y,Ns.x,0];return!Al(e,ur,dr,fr,za)||(e=[1,0,0,0,1,0,0,0,1],!Al(e,ur,dr,fr,za))?!1:(ka.crossVectors(ps,ms),e=[ka.x,ka.y,ka.z],Al(e,ur,dr,fr,za))}clampPoint(t,e){return e.copy(t).clamp(this.min,this.max)}distanceToPoint(t){return this.clampPoint(t,gi).distanceTo(t)}getBoundingSphere(t){return this.isEmpty()?t.makeEmpty():(this.getCenter(t.center),t.radius=this.getSize(gi).length()*.5),t}intersect(t){return this.min.max(t.min),this.max.min(t.max),this.isEmpty()&&this.makeEmpty(),this}union(t){return this.min.min(t.min),this.max.max(t.max),this}applyMatrix4(t){return this.isEmpty()?this:(Zi[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(t),Zi[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(t),Zi[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(t),Zi[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(t),Zi[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(t),Zi[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(t),Zi[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(t),Zi[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(t),this.setFromPoints(Zi),this)}translate(t){return this.min.add(t),this.max.add(t),this}equals(t){return t.min.equals(this.min)&&t.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(t){return this.min.fromArray(t.min),this.max.fromArray(t.max),this}}const Zi=[new V,new V,new V,new V,new V,new V,new V,new V],gi=new V,Ba=new wa,ur=new V,dr=new V,fr=new V,ps=new V,ms=new V,Ns=new V,qr=new V,za=new V,ka=new V,Is=new V;function Al(n,t,e,i,s){for(let r=0,a=n.length-3;r<=a;r+=3){Is.fromArray(n,r);const o=s.x*Math.abs(Is.x)+s.y*Math.abs(Is.y)+s.z*Math.abs(Is.z),c=t.dot(Is),l=e.dot(Is),h=i.dot(Is);if(Math.max(-Math.max(c,l,h),Math.min(c,l,h))>o)return!1}return!0}const an=new V,Ha=new Jt;let e_=0;class ns extends Cs{constructor(t,e,i=!1){if(super(),Array.isArray(t))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:e_++}),this.name="",this.array=t,this.itemSize=e,this.count=t!==void 0?t.length/e:0,this.normalized=i,this.usage=Ng,this.updateRanges=[],this.gpuType=Bi,this.version=0,this._normalizationScale=t!==void 0?Sh(t):void 0}onUploadCallback(){}set needsUpdate(t){t===!0&&this.version++}setUsage(t){return this.usage=t,this}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}copy(t){return this.name=t.name,this.array=new t.array.constructor(t.array),this.itemSize=t.itemSize,this.count=t.count,this.normalized=t.normalized,this.usage=t.usage,this.gpuType=t.gpuType,this._normalizationScale=t._normalizationScale,this}copyAt(t,e,i){t*=this.itemSize,i*=e.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[t+s]=e.array[i+s];return this}copyArray(t){return this.array.set(t),this}applyMatrix3(t){if(this.itemSize===2)for(let e=0,i=this.count;e<i;e++)Ha.fromBufferAttribute(this,e),Ha.applyMatrix3(t),this.setXY(e,Ha.x,Ha.y);else if(this.itemSize===3)for(let e=0,i=this.count;e<i;e++)an.fromBufferAttribute(this,e),an.applyMatrix3(t),this.setXYZ(e,an.x,an.y,an.z);return this}applyMatrix4(t){for(let e=0,i=this.count;e<i;e++)an.fromBufferAttribute(this,e),an.applyMatrix4(t),this.setXYZ(e,an.x,an.y,an.z);return this}applyNormalMatrix(t){for(let e=0,i=this.count;e<i;e++)an.fromBufferAttribute(this,e),an.applyNormalMatrix(t),this.setXYZ(e,an.x,an.y,an.z);return this}transformDirection(t){for(let e=0,i=this.count;e<i;e++)an.fromBufferAttribute(this,e),an.transformDirection(t),this.setXYZ(e,an.x,an.y,an.z);return this}set(t,e=0){return this.array.set(t,e),this}getComponent(t,e){let i=this.array[t*this.itemSize+e];return this.normalized&&(i=this._denormalize(i)),i}setComponent(t,e,i){return this.normalized&&(i=this._normalize(i)),this.array[t*this.itemSize+e]=i,this}getX(t){let e=this.array[t*this.itemSize];return this.normalized&&(e=this._denormalize(e)),e}setX(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize]=e,this}getY(t){let e=this.array[t*this.itemSize+1];return this.normalized&&(e=this._denormalize(e)),e}setY(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+1]=e,this}getZ(t){let e=this.array[t*this.itemSize+2];return this.normalized&&(e=this._denormalize(e)),e}setZ(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+2]=e,this}getW(t){let e=this.array[t*this.itemSize+3];return this.normalized&&(e=this._denormalize(e)),e}setW(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+3]=e,this}setXY(t,e,i){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),i=this._normalize(i)),this.array[t+0]=e,this.array[t+1]=i,this}setXYZ(t,e,i,s){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),i=this._normalize(i),s=this._normalize(s)),this.array[t+0]=e,this.array[t+1]=i,this.array[t+2]=s,this}setXYZW(t,e,i,s,r){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),i=this._normalize(i),s=this._normalize(s),r=this._normalize(r)),this.array[t+0]=e,this.array[t+1]=i,this.array[t+2]=s,this.array[t+3]=r,this}onUpload(t){return this.onUploadCallback=t,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){const t={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return t.name=this.name,t.usage=this.usage,t.gpuType=this.gpuType,t}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(t){const e=this._normalizationScale;return e!==void 0?Math.max(t/e,-1):kg(t,this.array)}_normalize(t){const e=this._normalizationScale;return e!==void 0?Math.round(t*e):Hg(t,this.array)}}class Zf extends ns{constructor(t,e,i){super(new Uint16Array(t),e,i)}}class Jf extends ns{constructor(t,e,i){super(new Uint32Array(t),e,i)}}class We extends ns{constructor(t,e,i){super(new Float32Array(t),e,i)}}const n_=new wa,Kr=new V,Rl=new V;class Ta{constructor(t=new V,e=-1){this.isSphere=!0,this.center=t,this.radius=e}set(t,e){return this.center.copy(t),this.radius=e,this}setFromPoints(t,e){const i=this.center;e!==void 0?i.copy(e):n_.setFromPoints(t).getCenter(i);let s=0;for(let r=0,a=t.length;r<a;r++)s=Math.max(s,i.distanceToSquared(t[r]));return this.radius=Math.sqrt(s),this}copy(t){return this.center.copy(t.center),this.radius=t.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(t){return t.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(t){return t.distanceTo(this.center)-this.radius}intersectsSphere(t){const e=this.radius+t.radius;return t.center.distanceToSquared(this.center)<=e*e}intersectsBox(t){return t.intersectsSphere(this)}intersectsPlane(t){return Math.abs(t.distanceToPoint(this.center))<=this.radius}clampPoint(t,e){const i=this.center.distanceToSquared(t);return e.copy(t),i>this.radius*this.radius&&(e.sub(this.center).normalize(),e.multiplyScalar(this.radius).add(this.center)),e}getBoundingBox(t){return this.isEmpty()?(t.makeEmpty(),t):(t.set(this.center,this.center),t.expandByScalar(this.radius),t)}applyMatrix4(t){return this.center.applyMatrix4(t),this.radius=this.radius*t.getMaxScaleOnAxis(),this}translate(t){return this.center.add(t),this}expandByPoint(t){if(this.isEmpty())return this.center.copy(t),this.radius=0,this;Kr.subVectors(t,this.center);const e=Kr.lengthSq();if(e>this.radius*this.radius){const i=Math.sqrt(e),s=(i-this.radius)*.5;this.center.addScaledVector(Kr,s/i),this.radius+=s}return this}union(t){return t.isEmpty()?this:this.isEmpty()?(this.copy(t),this):(this.center.equals(t.center)===!0?this.radius=Math.max(this.radius,t.radius):(Rl.subVectors(t.center,this.center).setLength(t.radius),this.expandByPoint(Kr.copy(t.center).add(Rl)),this.expandByPoint(Kr.copy(t.center).sub(Rl))),this)}equals(t){return t.center.equals(this.center)&&t.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(t){return this.radius=t.radius,this.center.fromArray(t.center),this}}let i_=0;const ni=new Le,Cl=new Tn,pr=new V,Kn=new wa,Zr=new wa,En=new V;class ln extends Cs{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:i_++}),this.uuid=ba(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(t){return Array.isArray(t)?this.index=new(Ig(t)?Jf:Zf)(t,1):this.index=t,this}setIndirect(t,e=0){return this.indirect=t,this.indirectOffset=e,this}getIndirect(){return this.indirect}getAttribute(t){return this.attributes[t]}setAttribute(t,e){return this.attributes[t]=e,this}deleteAttribute(t){return delete this.attributes[t],this}hasAttribute(t){return this.attributes[t]!==void 0}addGroup(t,e,i=0){this.groups.push({start:t,count:e,materialIndex:i})}clearGroups(){this.groups=[]}setDrawRange(t,e){this.drawRange.start=t,this.drawRange.count=e}applyMatrix4(t){const e=this.attributes.position;e!==void 0&&(e.applyMatrix4(t),e.needsUpdate=!0);const i=this.attributes.normal;if(i!==void 0){const r=new te().getNormalMatrix(t);i.applyNormalMatrix(r),i.needsUpdate=!0}const s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(t),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(t){return ni.makeRotationFromQuaternion(t),this.applyMatrix4(ni),this}rotateX(t){return ni.makeRotationX(t),this.applyMatrix4(ni),this}rotateY(t){return ni.makeRotationY(t),this.applyMatrix4(ni),this}rotateZ(t){return ni.makeRotationZ(t),this.applyMatrix4(ni),this}translate(t,e,i){return ni.makeTranslation(t,e,i),this.applyMatrix4(ni),this}scale(t,e,i){return ni.makeScale(t,e,i),this.applyMatrix4(ni),this}lookAt(t){return Cl.lookAt(t),Cl.updateMatrix(),this.applyMatrix4(Cl.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(pr).negate(),this.translate(pr.x,pr.y,pr.z),this}setFromPoints(t){const e=this.getAttribute("position");if(e===void 0){const i=[];for(let s=0,r=t.length;s<r;s++){const a=t[s];i.push(a.x,a.y,a.z||0)}this.setAttribute("position",new We(i,3))}else{const i=Math.min(t.length,e.count);for(let s=0;s<i;s++){const r=t[s];e.setXYZ(s,r.x,r.y,r.z||0)}t.length>e.count&&Kt("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),e.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new wa);const t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){ve("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new V(-1/0,-1/0,-1/0),new V(1/0,1/0,1/0));return}if(t!==void 0){if(this.boundingBox.setFromBufferAttribute(t),e)for(let i=0,s=e.length;i<s;i++){const r=e[i];Kn.setFromBufferAttribute(r),this.morphTargetsRelative?(En.addVectors(this.boundingBox.min,Kn.min),this.boundingBox.expandByPoint(En),En.addVectors(this.boundingBox.max,Kn.max),this.boundingBox.expandByPoint(En)):(this.boundingBox.expandByPoint(Kn.min),this.boundingBox.expandByPoint(Kn.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&ve('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Ta);const t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){ve("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new V,1/0);return}if(t){const i=this.boundingSphere.center;if(Kn.setFromBufferAttribute(t),e)for(let r=0,a=e.length;r<a;r++){const o=e[r];Zr.setFromBufferAttribute(o),this.morphTargetsRelative?(En.addVectors(Kn.min,Zr.min),Kn.expandByPoint(En),En.addVectors(Kn.max,Zr.max),Kn.expandByPoint(En)):(Kn.expandByPoint(Zr.min),Kn.expandByPoint(Zr.max))}Kn.getCenter(i);let s=0;for(let r=0,a=t.count;r<a;r++)En.fromBufferAttribute(t,r),s=Math.max(s,i.distanceToSquared(En));if(e)for(let r=0,a=e.length;r<a;r++){const o=e[r],c=this.morphTargetsRelative;for(let l=0,h=o.count;l<h;l++)En.fromBufferAttribute(o,l),c&&(pr.fromBufferAttribute(t,l),En.add(pr)),s=Math.max(s,i.distanceToSquared(En))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&ve('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){const t=this.index,e=this.attributes;if(t===null||e.position===void 0||e.normal===void 0||e.uv===void 0){ve("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}const i=e.position,s=e.normal,r=e.uv;let a=this.getAttribute("tangent");(a===void 0||a.count!==i.count)&&(a=new ns(new Float32Array(4*i.count),4),this.setAttribute("tangent",a));const o=[],c=[],l=new Uint8Array(i.count);for(let z=0;z<i.count;z++)o[z]=new V,c[z]=new V;const h=new V,d=new V,u=new V,m=new Jt,v=new Jt,M=new Jt,p=new V,f=new V;function x(z,U,D){l[z]=l[U]=l[D]=1,h.fromBufferAttribute(i,z),d.fromBufferAttribute(i,U),u.fromBufferAttribute(i,D),m.fromBufferAttribute(r,z),v.fromBufferAttribute(r,U),M.fromBufferAttribute(r,D),d.sub(h),u.sub(h),v.sub(m),M.sub(m);const I=1/(v.x*M.y-M.x*v.y);isFinite(I)&&(p.copy(d).multiplyScalar(M.y).addScaledVector(u,-v.y).multiplyScalar(I),f.copy(u).multiplyScalar(v.x).addScaledVector(d,-M.x).multiplyScalar(I),o[z].add(p),o[U].add(p),o[D].add(p),c[z].add(f),c[U].add(f),c[D].add(f))}let A=this.groups;A.length===0&&(A=[{start:0,count:t.count}]);for(let z=0,U=A.length;z<U;++z){const D=A[z],I=D.start,B=D.count;for(let L=I,G=I+B;L<G;L+=3)x(t.getX(L+0),t.getX(L+1),t.getX(L+2))}const y=new V,R=new V,E=new V,g=new V;function T(z){E.fromBufferAttribute(s,z),g.copy(E);const U=o[z];y.copy(U),y.sub(E.multiplyScalar(E.dot(U))).normalize(),R.crossVectors(g,U);const I=R.dot(c[z])<0?-1:1;a.setXYZW(z,y.x,y.y,y.z,I)}for(let z=0,U=i.count;z<U;++z)l[z]&&T(z);this._transformed=!0}computeVertexNormals(){const t=this.index,e=this.getAttribute("position");if(e!==void 0){let i=this.getAttribute("normal");if(i===void 0||i.count!==e.count)i=new ns(new Float32Array(e.count*3),3),this.setAttribute("normal",i);else for(let u=0,m=i.count;u<m;u++)i.setXYZ(u,0,0,0);const s=new V,r=new V,a=new V,o=new V,c=new V,l=new V,h=new V,d=new V;if(t)for(let u=0,m=t.count;u<m;u+=3){const v=t.getX(u+0),M=t.getX(u+1),p=t.getX(u+2);s.fromBufferAttribute(e,v),r.fromBufferAttribute(e,M),a.fromBufferAttribute(e,p),h.subVectors(a,r),d.subVectors(s,r),h.cross(d),o.fromBufferAttribute(i,v),c.fromBufferAttribute(i,M),l.fromBufferAttribute(i,p),o.add(h),c.add(h),l.add(h),i.setXYZ(v,o.x,o.y,o.z),i.setXYZ(M,c.x,c.y,c.z),i.setXYZ(p,l.x,l.y,l.z)}else for(let u=0,m=e.count;u<m;u+=3)s.fromBufferAttribute(e,u+0),r.fromBufferAttribute(e,u+1),a.fromBufferAttribute(e,u+2),h.subVectors(a,r),d.subVectors(s,r),h.cross(d),i.setXYZ(u+0,h.x,h.y,h.z),i.setXYZ(u+1,h.x,h.y,h.z),i.setXYZ(u+2,h.x,h.y,h.z);this.normalizeNormals(),i.needsUpdate=!0}}normalizeNormals(){const t=this.attributes.normal;for(let e=0,i=t.count;e<i;e++)En.fromBufferAttribute(t,e),En.normalize(),t.setXYZ(e,En.x,En.y,En.z)}toNonIndexed(){function t(o,c){const l=o.array,h=o.itemSize,d=o.normalized,u=new l.constructor(c.length*h);let m=0,v=0;for(let M=0,p=c.length;M<p;M++){o.isInterleavedBufferAttribute?m=c[M]*o.data.stride+o.offset:m=c[M]*h;for(let f=0;f<h;f++)u[v++]=l[m++]}return new ns(u,h,d)}if(this.index===null)return Kt("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;const e=new ln,i=this.index.array,s=this.attributes;for(const o in s){const c=s[o],l=t(c,i);e.setAttribute(o,l)}const r=this.morphAttributes;for(const o in r){const c=[],l=r[o];for(let h=0,d=l.length;h<d;h++){const u=l[h],m=t(u,i);c.push(m)}e.morphAttributes[o]=c}e.morphTargetsRelative=this.morphTargetsRelative;const a=this.groups;for(let o=0,c=a.length;o<c;o++){const l=a[o];e.addGroup(l.start,l.count,l.materialIndex)}return e}toJSON(){const t={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(t.uuid=this.uuid,t.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,t.name=this.name,Object.keys(this.userData).length>0&&(t.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){const c=this.parameters;for(const l in c)c[l]!==void 0&&(t[l]=c[l]);return t}t.data={attributes:{}};const e=this.index;e!==null&&(t.data.index={type:e.array.constructor.name,array:Array.prototype.slice.call(e.array)});const i=this.attributes;for(const c in i){const l=i[c];t.data.attributes[c]=l.toJSON(t.data)}const s={};let r=!1;for(const c in this.morphAttributes){const l=this.morphAttributes[c],h=[];for(let d=0,u=l.length;d<u;d++){const m=l[d];h.push(m.toJSON(t.data))}h.length>0&&(s[c]=h,r=!0)}r&&(t.data.morphAttributes=s,t.data.morphTargetsRelative=this.morphTargetsRelative);const a=this.groups;a.length>0&&(t.data.groups=JSON.parse(JSON.stringify(a)));const o=this.boundingSphere;return o!==null&&(t.data.boundingSphere=o.toJSON()),t}clone(){return new this.constructor().copy(this)}copy(t){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;const e={};this.name=t.name;const i=t.index;i!==null&&this.setIndex(i.clone());const s=t.attributes;for(const l in s){const h=s[l];this.setAttribute(l,h.clone(e))}const r=t.morphAttributes;for(const l in r){const h=[],d=r[l];for(let u=0,m=d.length;u<m;u++)h.push(d[u].clone(e));this.morphAttributes[l]=h}this.morphTargetsRelative=t.morphTargetsRelative;const a=t.groups;for(let l=0,h=a.length;l<h;l++){const d=a[l];this.addGroup(d.start,d.count,d.materialIndex)}const o=t.boundingBox;o!==null&&(this.boundingBox=o.clone());const c=t.boundingSphere;return c!==null&&(this.boundingSphere=c.clone()),this.drawRange.start=t.drawRange.start,this.drawRange.count=t.drawRange.count,this.userData=t.userData,this._transformed=t._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}}const Pl=new V,s_=new V,r_=new te;class Si{constructor(t=new V(1,0,0),e=0){this.isPlane=!0,this.normal=t,this.constant=e}set(t,e){return this.normal.copy(t),this.constant=e,this}setComponents(t,e,i,s){return this.normal.set(t,e,i),this.constant=s,this}setFromNormalAndCoplanarPoint(t,e){return this.normal.copy(t),this.constant=-e.dot(this.normal),this}setFromCoplanarPoints(t,e,i){const s=Pl.subVectors(i,e).cross(s_.subVectors(t,e)).normalize();return this.setFromNormalAndCoplanarPoint(s,t),this}copy(t){return this.normal.copy(t.normal),this.constant=t.constant,this}normalize(){const t=1/this.normal.length();return this.normal.multiplyScalar(t),this.constant*=t,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(t){return this.normal.dot(t)+this.constant}distanceToSphere(t){return this.distanceToPoint(t.center)-t.radius}projectPoint(t,e){return e.copy(t).addScaledVector(this.normal,-this.distanceToPoint(t))}intersectLine(t,e,i=!0){const s=t.delta(Pl),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(t.start)===0?e.copy(t.start):null;const a=-(t.start.dot(this.normal)+this.constant)/r;return i===!0&&(a<0||a>1)?null:e.copy(t.start).addScaledVector(s,a)}intersectsLine(t){const e=this.distanceToPoint(t.start),i=this.distanceToPoint(t.end);return e<0&&i>0||i<0&&e>0}intersectsBox(t){return t.intersectsPlane(this)}intersectsSphere(t){return t.intersectsPlane(this)}coplanarPoint(t){return t.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(t,e){const i=e||r_.getNormalMatrix(t),s=this.coplanarPoint(Pl).applyMatrix4(t),r=this.normal.applyMatrix3(i).normalize();return this.constant=-s.dot(r),this}translate(t){return this.constant-=t.dot(this.normal),this}equals(t){return t.normal.equals(this.normal)&&t.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(t){return this.normal.fromArray(t.normal),this.constant=t.constant,this}}let a_=0;class Ir extends Cs{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:a_++}),this.uuid=ba(),this.name="",this.type="Material",this.blending=ha,this.side=Es,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=wf,this.blendDst=Tf,this.blendEquation=vr,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new le(0,0,0),this.blendAlpha=0,this.depthFunc=ga,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=Ag,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=ul,this.stencilZFail=ul,this.stencilZPass=ul,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(t){this._alphaTest>0!=t>0&&this.version++,this._alphaTest=t}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(t){if(t!==void 0)for(const e in t){const i=t[e];if(i===void 0){Kt(`Material: parameter '${e}' has value of undefined.`);continue}const s=this[e];if(s===void 0){Kt(`Material: '${e}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(i):s&&s.isVector2&&i&&i.isVector2||s&&s.isEuler&&i&&i.isEuler||s&&s.isVector3&&i&&i.isVector3?s.copy(i):this[e]=i}}toJSON(t){const e=t===void 0||typeof t=="string";e&&(t={textures:{},images:{}});const i={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};i.uuid=this.uuid,i.type=this.type,i.blending=this.blending,i.side=this.side,i.shadowSide=this.shadowSide,i.vertexColors=this.vertexColors,i.opacity=this.opacity,i.transparent=this.transparent,i.blendSrc=this.blendSrc,i.blendDst=this.blendDst,i.blendEquation=this.blendEquation,i.blendSrcAlpha=this.blendSrcAlpha,i.blendDstAlpha=this.blendDstAlpha,i.blendEquationAlpha=this.blendEquationAlpha,i.blendColor=this.blendColor.getHex(),i.blendAlpha=this.blendAlpha,i.depthFunc=this.depthFunc,i.depthTest=this.depthTest,i.depthWrite=this.depthWrite,i.colorWrite=this.colorWrite,i.clipIntersection=this.clipIntersection,i.clipShadows=this.clipShadows,i.stencilWriteMask=this.stencilWriteMask,i.stencilFunc=this.stencilFunc,i.stencilRef=this.stencilRef,i.stencilFuncMask=this.stencilFuncMask,i.stencilFail=this.stencilFail,i.stencilZFail=this.stencilZFail,i.stencilZPass=this.stencilZPass,i.stencilWrite=this.stencilWrite,i.polygonOffset=this.polygonOffset,i.polygonOffsetFactor=this.polygonOffsetFactor,i.polygonOffsetUnits=this.polygonOffsetUnits,i.dithering=this.dithering,i.alphaTest=this.alphaTest,i.alphaHash=this.alphaHash,i.alphaToCoverage=this.alphaToCoverage,i.premultipliedAlpha=this.premultipliedAlpha,i.forceSinglePass=this.forceSinglePass,i.allowOverride=this.allowOverride,i.visible=this.visible,i.toneMapped=this.toneMapped,i.name=this.name,this.color&&this.color.isColor&&(i.color=this.color.getHex()),this.roughness!==void 0&&(i.roughness=this.roughness),this.metalness!==void 0&&(i.metalness=this.metalness),this.sheen!==void 0&&(i.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(i.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(i.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(i.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(i.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(i.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(i.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(i.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(i.shininess=this.shininess),this.clearcoat!==void 0&&(i.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(i.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(i.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(i.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(t).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(i.clearcoatMap=this.clearcoatMap.toJSON(t).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(i.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(t).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(i.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(t).uuid,i.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(i.sheenColorMap=this.sheenColorMap.toJSON(t).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(i.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(t).uuid),this.dispersion!==void 0&&(i.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(i.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(i.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(i.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(i.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(i.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(i.iridescenceMap=this.iridescenceMap.toJSON(t).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(i.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(t).uuid),this.anisotropy!==void 0&&(i.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(i.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(i.anisotropyMap=this.anisotropyMap.toJSON(t).uuid),this.map&&this.map.isTexture&&(i.map=this.map.toJSON(t).uuid),this.matcap&&this.matcap.isTexture&&(i.matcap=this.matcap.toJSON(t).uuid),this.alphaMap&&this.alphaMap.isTexture&&(i.alphaMap=this.alphaMap.toJSON(t).uuid),this.lightMap&&this.lightMap.isTexture&&(i.lightMap=this.lightMap.toJSON(t).uuid,i.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(i.aoMap=this.aoMap.toJSON(t).uuid,i.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(i.bumpMap=this.bumpMap.toJSON(t).uuid,i.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(i.normalMap=this.normalMap.toJSON(t).uuid,i.normalMapType=this.normalMapType,i.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(i.displacementMap=this.displacementMap.toJSON(t).uuid,i.displacementScale=this.displacementScale,i.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(i.roughnessMap=this.roughnessMap.toJSON(t).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(i.metalnessMap=this.metalnessMap.toJSON(t).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(i.emissiveMap=this.emissiveMap.toJSON(t).uuid),this.specularMap&&this.specularMap.isTexture&&(i.specularMap=this.specularMap.toJSON(t).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(i.specularIntensityMap=this.specularIntensityMap.toJSON(t).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(i.specularColorMap=this.specularColorMap.toJSON(t).uuid),this.envMap&&this.envMap.isTexture&&(i.envMap=this.envMap.toJSON(t).uuid,this.combine!==void 0&&(i.combine=this.combine)),this.envMapRotation!==void 0&&(i.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(i.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(i.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(i.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(i.gradientMap=this.gradientMap.toJSON(t).uuid),this.transmission!==void 0&&(i.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(i.transmissionMap=this.transmissionMap.toJSON(t).uuid),this.thickness!==void 0&&(i.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(i.thicknessMap=this.thicknessMap.toJSON(t).uuid),this.attenuationDistance!==void 0&&(i.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(i.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(i.size=this.size),this.sizeAttenuation!==void 0&&(i.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(i.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(i.rotation=this.rotation),this.depthPacking!==void 0&&(i.depthPacking=this.depthPacking),this.linewidth!==void 0&&(i.linewidth=this.linewidth),this.linecap!==void 0&&(i.linecap=this.linecap),this.linejoin!==void 0&&(i.linejoin=this.linejoin),this.dashSize!==void 0&&(i.dashSize=this.dashSize),this.gapSize!==void 0&&(i.gapSize=this.gapSize),this.scale!==void 0&&(i.scale=this.scale),this.wireframe!==void 0&&(i.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(i.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(i.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(i.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(i.flatShading=this.flatShading),this.fog!==void 0&&(i.fog=this.fog),Object.keys(this.userData).length>0&&(i.userData=this.userData);function s(r){const a=[];for(const o in r){const c=r[o];delete c.metadata,a.push(c)}return a}if(e){const r=s(t.textures),a=s(t.images);r.length>0&&(i.textures=r),a.length>0&&(i.images=a)}return i}fromJSON(t,e){if(t.uuid!==void 0&&(this.uuid=t.uuid),t.name!==void 0&&(this.name=t.name),t.color!==void 0&&this.color!==void 0&&this.color.setHex(t.color),t.roughness!==void 0&&(this.roughness=t.roughness),t.metalness!==void 0&&(this.metalness=t.metalness),t.sheen!==void 0&&(this.sheen=t.sheen),t.sheenColor!==void 0&&(this.sheenColor=new le().setHex(t.sheenColor)),t.sheenRoughness!==void 0&&(this.sheenRoughness=t.sheenRoughness),t.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(t.emissive),t.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(t.specular),t.specularIntensity!==void 0&&(this.specularIntensity=t.specularIntensity),t.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(t.specularColor),t.shininess!==void 0&&(this.shininess=t.shininess),t.clearcoat!==void 0&&(this.clearcoat=t.clearcoat),t.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=t.clearcoatRoughness),t.diffuseRoughness!==void 0&&(this.diffuseRoughness=t.diffuseRoughness),t.dispersion!==void 0&&(this.dispersion=t.dispersion),t.retroreflectivity!==void 0&&(this.retroreflectivity=t.retroreflectivity),t.iridescence!==void 0&&(this.iridescence=t.iridescence),t.iridescenceIOR!==void 0&&(this.iridescenceIOR=t.iridescenceIOR),t.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessMinimum),t.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=t.iridescenceThicknessMaximum),t.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=t.iridescenceThicknessRange[1]),t.transmission!==void 0&&(this.transmission=t.transmission),t.thickness!==void 0&&(this.thickness=t.thickness),t.attenuationDistance!==void 0&&(this.attenuationDistance=t.attenuationDistance),t.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(t.attenuationColor),t.anisotropy!==void 0&&(this.anisotropy=t.anisotropy),t.anisotropyRotation!==void 0&&(this.anisotropyRotation=t.anisotropyRotation),t.fog!==void 0&&(this.fog=t.fog),t.flatShading!==void 0&&(this.flatShading=t.flatShading),t.blending!==void 0&&(this.blending=t.blending),t.combine!==void 0&&(this.combine=t.combine),t.side!==void 0&&(this.side=t.side),t.shadowSide!==void 0&&(this.shadowSide=t.shadowSide),t.opacity!==void 0&&(this.opacity=t.opacity),t.transparent!==void 0&&(this.transparent=t.transparent),t.alphaTest!==void 0&&(this.alphaTest=t.alphaTest),t.alphaHash!==void 0&&(this.alphaHash=t.alphaHash),t.depthFunc!==void 0&&(this.depthFunc=t.depthFunc),t.depthTest!==void 0&&(this.depthTest=t.depthTest),t.depthWrite!==void 0&&(this.depthWrite=t.depthWrite),t.colorWrite!==void 0&&(this.colorWrite=t.colorWrite),t.clippingPlanes!==void 0&&(this.clippingPlanes=t.clippingPlanes.map(i=>new Si().fromJSON(i))),t.clipIntersection!==void 0&&(this.clipIntersection=t.clipIntersection),t.clipShadows!==void 0&&(this.clipShadows=t.clipShadows),t.depthPacking!==void 0&&(this.depthPacking=t.depthPacking),t.blendSrc!==void 0&&(this.blendSrc=t.blendSrc),t.blendDst!==void 0&&(this.blendDst=t.blendDst),t.blendEquation!==void 0&&(this.blendEquation=t.blendEquation),t.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=t.blendSrcAlpha),t.blendDstAlpha!==void 0&&(this.blendDstAlpha=t.blendDstAlpha),t.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=t.blendEquationAlpha),t.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(t.blendColor),t.blendAlpha!==void 0&&(this.blendAlpha=t.blendAlpha),t.stencilWriteMask!==void 0&&(this.stencilWriteMask=t.stencilWriteMask),t.stencilFunc!==void 0&&(this.stencilFunc=t.stencilFunc),t.stencilRef!==void 0&&(this.stencilRef=t.stencilRef),t.stencilFuncMask!==void 0&&(this.stencilFuncMask=t.stencilFuncMask),t.stencilFail!==void 0&&(this.stencilFail=t.stencilFail),t.stencilZFail!==void 0&&(this.stencilZFail=t.stencilZFail),t.stencilZPass!==void 0&&(this.stencilZPass=t.stencilZPass),t.stencilWrite!==void 0&&(this.stencilWrite=t.stencilWrite),t.wireframe!==void 0&&(this.wireframe=t.wireframe),t.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=t.wireframeLinewidth),t.wireframeLinecap!==void 0&&(this.wireframeLinecap=t.wireframeLinecap),t.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=t.wireframeLinejoin),t.rotation!==void 0&&(this.rotation=t.rotation),t.linewidth!==void 0&&(this.linewidth=t.linewidth),t.linecap!==void 0&&(this.linecap=t.linecap),t.linejoin!==void 0&&(this.linejoin=t.linejoin),t.dashSize!==void 0&&(this.dashSize=t.dashSize),t.gapSize!==void 0&&(this.gapSize=t.gapSize),t.scale!==void 0&&(this.scale=t.scale),t.polygonOffset!==void 0&&(this.polygonOffset=t.polygonOffset),t.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=t.polygonOffsetFactor),t.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=t.polygonOffsetUnits),t.dithering!==void 0&&(this.dithering=t.dithering),t.alphaToCoverage!==void 0&&(this.alphaToCoverage=t.alphaToCoverage),t.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=t.premultipliedAlpha),t.forceSinglePass!==void 0&&(this.forceSinglePass=t.forceSinglePass),t.allowOverride!==void 0&&(this.allowOverride=t.allowOverride),t.visible!==void 0&&(this.visible=t.visible),t.toneMapped!==void 0&&(this.toneMapped=t.toneMapped),t.userData!==void 0&&(this.userData=t.userData),t.vertexColors!==void 0&&(typeof t.vertexColors=="number"?this.vertexColors=t.vertexColors>0:this.vertexColors=t.vertexColors),t.size!==void 0&&(this.size=t.size),t.sizeAttenuation!==void 0&&(this.sizeAttenuation=t.sizeAttenuation),t.map!==void 0&&(this.map=e[t.map]||null),t.matcap!==void 0&&(this.matcap=e[t.matcap]||null),t.alphaMap!==void 0&&(this.alphaMap=e[t.alphaMap]||null),t.bumpMap!==void 0&&(this.bumpMap=e[t.bumpMap]||null),t.bumpScale!==void 0&&(this.bumpScale=t.bumpScale),t.normalMap!==void 0&&(this.normalMap=e[t.normalMap]||null),t.normalMapType!==void 0&&(this.normalMapType=t.normalMapType),t.normalScale!==void 0){let i=t.normalScale;Array.isArray(i)===!1&&(i=[i,i]),this.normalScale=new Jt().fromArray(i)}return t.displacementMap!==void 0&&(this.displacementMap=e[t.displacementMap]||null),t.displacementScale!==void 0&&(this.displacementScale=t.displacementScale),t.displacementBias!==void 0&&(this.displacementBias=t.displacementBias),t.roughnessMap!==void 0&&(this.roughnessMap=e[t.roughnessMap]||null),t.metalnessMap!==void 0&&(this.metalnessMap=e[t.metalnessMap]||null),t.emissiveMap!==void 0&&(this.emissiveMap=e[t.emissiveMap]||null),t.emissiveIntensity!==void 0&&(this.emissiveIntensity=t.emissiveIntensity),t.specularMap!==void 0&&(this.specularMap=e[t.specularMap]||null),t.specularIntensityMap!==void 0&&(this.specularIntensityMap=e[t.specularIntensityMap]||null),t.specularColorMap!==void 0&&(this.specularColorMap=e[t.specularColorMap]||null),t.envMap!==void 0&&(this.envMap=e[t.envMap]||null),t.envMapRotation!==void 0&&this.envMapRotation.fromArray(t.envMapRotation),t.envMapIntensity!==void 0&&(this.envMapIntensity=t.envMapIntensity),t.reflectivity!==void 0&&(this.reflectivity=t.reflectivity),t.refractionRatio!==void 0&&(this.refractionRatio=t.refractionRatio),t.lightMap!==void 0&&(this.lightMap=e[t.lightMap]||null),t.lightMapIntensity!==void 0&&(this.lightMapIntensity=t.lightMapIntensity),t.aoMap!==void 0&&(this.aoMap=e[t.aoMap]||null),t.aoMapIntensity!==void 0&&(this.aoMapIntensity=t.aoMapIntensity),t.gradientMap!==void 0&&(this.gradientMap=e[t.gradientMap]||null),t.clearcoatMap!==void 0&&(this.clearcoatMap=e[t.clearcoatMap]||null),t.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=e[t.clearcoatRoughnessMap]||null),t.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=e[t.clearcoatNormalMap]||null),t.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new Jt().fromArray(t.clearcoatNormalScale)),t.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=e[t.diffuseRoughnessMap]||null),t.iridescenceMap!==void 0&&(this.iridescenceMap=e[t.iridescenceMap]||null),t.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=e[t.iridescenceThicknessMap]||null),t.transmissionMap!==void 0&&(this.transmissionMap=e[t.transmissionMap]||null),t.thicknessMap!==void 0&&(this.thicknessMap=e[t.thicknessMap]||null),t.anisotropyMap!==void 0&&(this.anisotropyMap=e[t.anisotropyMap]||null),t.sheenColorMap!==void 0&&(this.sheenColorMap=e[t.sheenColorMap]||null),t.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=e[t.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(t){this.name=t.name,this.blending=t.blending,this.side=t.side,this.vertexColors=t.vertexColors,this.opacity=t.opacity,this.transparent=t.transparent,this.blendSrc=t.blendSrc,this.blendDst=t.blendDst,this.blendEquation=t.blendEquation,this.blendSrcAlpha=t.blendSrcAlpha,this.blendDstAlpha=t.blendDstAlpha,this.blendEquationAlpha=t.blendEquationAlpha,this.blendColor.copy(t.blendColor),this.blendAlpha=t.blendAlpha,this.depthFunc=t.depthFunc,this.depthTest=t.depthTest,this.depthWrite=t.depthWrite,this.stencilWriteMask=t.stencilWriteMask,this.stencilFunc=t.stencilFunc,this.stencilRef=t.stencilRef,this.stencilFuncMask=t.stencilFuncMask,this.stencilFail=t.stencilFail,this.stencilZFail=t.stencilZFail,this.stencilZPass=t.stencilZPass,this.stencilWrite=t.stencilWrite;const e=t.clippingPlanes;let i=null;if(e!==null){const s=e.length;i=new Array(s);for(let r=0;r!==s;++r)i[r]=e[r].clone()}return this.clippingPlanes=i,this.clipIntersection=t.clipIntersection,this.clipShadows=t.clipShadows,this.shadowSide=t.shadowSide,this.colorWrite=t.colorWrite,this.precision=t.precision,this.polygonOffset=t.polygonOffset,this.polygonOffsetFactor=t.polygonOffsetFactor,this.polygonOffsetUnits=t.polygonOffsetUnits,this.dithering=t.dithering,this.alphaTest=t.alphaTest,this.alphaHash=t.alphaHash,this.alphaToCoverage=t.alphaToCoverage,this.premultipliedAlpha=t.premultipliedAlpha,this.forceSinglePass=t.forceSinglePass,this.allowOverride=t.allowOverride,this.visible=t.visible,this.toneMapped=t.toneMapped,this.userData=JSON.parse(JSON.stringify(t.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(t){t===!0&&this.version++}}const Ji=new V,Ll=new V,Ga=new V,Va=new V;class Oo{constructor(t=new V,e=new V(0,0,-1)){this.origin=t,this.direction=e}set(t,e){return this.origin.copy(t),this.direction.copy(e),this}copy(t){return this.origin.copy(t.origin),this.direction.copy(t.direction),this}at(t,e){return e.copy(this.origin).addScaledVector(this.direction,t)}lookAt(t){return this.direction.copy(t).sub(this.origin).normalize(),this}recast(t){return this.origin.copy(this.at(t,Ji)),this}closestPointToPoint(t,e){e.subVectors(t,this.origin);const i=e.dot(this.direction);return i<0?e.copy(this.origin):e.copy(this.origin).addScaledVector(this.direction,i)}distanceToPoint(t){return Math.sqrt(this.distanceSqToPoint(t))}distanceSqToPoint(t){const e=Ji.subVectors(t,this.origin).dot(this.direction);return e<0?this.origin.distanceToSquared(t):(Ji.copy(this.origin).addScaledVector(this.direction,e),Ji.distanceToSquared(t))}distanceSqToSegment(t,e,i,s){Ll.copy(t).add(e).multiplyScalar(.5),Ga.copy(e).sub(t).normalize(),Va.copy(this.origin).sub(Ll);const r=t.distanceTo(e)*.5,a=-this.direction.dot(Ga),o=Va.dot(this.direction),c=-Va.dot(Ga),l=Va.lengthSq(),h=Math.abs(1-a*a);let d,u,m,v;if(h>0)if(d=a*c-o,u=a*o-c,v=r*h,d>=0)if(u>=-v)if(u<=v){const M=1/h;d*=M,u*=M,m=d*(d+a*u+2*o)+u*(a*d+u+2*c)+l}else u=r,d=Math.max(0,-(a*u+o)),m=-d*d+u*(u+2*c)+l;else u=-r,d=Math.max(0,-(a*u+o)),m=-d*d+u*(u+2*c)+l;else u<=-v?(d=Math.max(0,-(-a*r+o)),u=d>0?-r:Math.min(Math.max(-r,-c),r),m=-d*d+u*(u+2*c)+l):u<=v?(d=0,u=Math.min(Math.max(-r,-c),r),m=u*(u+2*c)+l):(d=Math.max(0,-(a*r+o)),u=d>0?r:Math.min(Math.max(-r,-c),r),m=-d*d+u*(u+2*c)+l);else u=a>0?-r:r,d=Math.max(0,-(a*u+o)),m=-d*d+u*(u+2*c)+l;return i&&i.copy(this.origin).addScaledVector(this.direction,d),s&&s.copy(Ll).addScaledVector(Ga,u),m}intersectSphere(t,e){if(t.radius<0)return null;Ji.subVectors(t.center,this.origin);const i=Ji.dot(this.direction),s=Ji.dot(Ji)-i*i,r=t.radius*t.radius;if(s>r)return null;const a=Math.sqrt(r-s),o=i-a,c=i+a;return c<0?null:o<0?this.at(c,e):this.at(o,e)}intersectsSphere(t){return t.radius<0?!1:this.distanceSqToPoint(t.center)<=t.radius*t.radius}distanceToPlane(t){const e=t.normal.dot(this.direction);if(e===0)return t.distanceToPoint(this.origin)===0?0:null;const i=-(this.origin.dot(t.normal)+t.constant)/e;return i>=0?i:null}intersectPlane(t,e){const i=this.distanceToPlane(t);return i===null?null:this.at(i,e)}intersectsPlane(t){const e=t.distanceToPoint(this.origin);return e===0||t.normal.dot(this.direction)*e<0}intersectBox(t,e){let i,s,r,a,o,c;const l=1/this.direction.x,h=1/this.direction.y,d=1/this.direction.z,u=this.origin;return l>=0?(i=(t.min.x-u.x)*l,s=(t.max.x-u.x)*l):(i=(t.max.x-u.x)*l,s=(t.min.x-u.x)*l),h>=0?(r=(t.min.y-u.y)*h,a=(t.max.y-u.y)*h):(r=(t.max.y-u.y)*h,a=(t.min.y-u.y)*h),i>a||r>s||((r>i||isNaN(i))&&(i=r),(a<s||isNaN(s))&&(s=a),d>=0?(o=(t.min.z-u.z)*d,c=(t.max.z-u.z)*d):(o=(t.max.z-u.z)*d,c=(t.min.z-u.z)*d),i>c||o>s)||((o>i||i!==i)&&(i=o),(c<s||s!==s)&&(s=c),s<0)?null:this.at(i>=0?i:s,e)}intersectsBox(t){return this.intersectBox(t,Ji)!==null}intersectTriangle(t,e,i,s,r){const a=this.origin,o=this.direction,c=o.x,l=o.y,h=o.z,d=t.x-a.x,u=t.y-a.y,m=t.z-a.z,v=e.x-a.x,M=e.y-a.y,p=e.z-a.z,f=i.x-a.x,x=i.y-a.y,A=i.z-a.z,y=Math.abs(c),R=Math.abs(l),E=Math.abs(h);let g,T,z,U,D,I,B,L,G,Y,k,lt;if(y>=R&&y>=E?(z=c,I=d,G=v,lt=f,c>=0?(g=l,T=h,U=u,D=m,B=M,L=p,Y=x,k=A):(g=h,T=l,U=m,D=u,B=p,L=M,Y=A,k=x)):R>=E?(z=l,I=u,G=M,lt=x,l>=0?(g=h,T=c,U=m,D=d,B=p,L=v,Y=A,k=f):(g=c,T=h,U=d,D=m,B=v,L=p,Y=f,k=A)):(z=h,I=m,G=p,lt=A,h>=0?(g=c,T=l,U=d,D=u,B=v,L=M,Y=f,k=x):(g=l,T=c,U=u,D=d,B=M,L=v,Y=x,k=f)),z===0)return null;const K=g/z,Q=T/z,nt=1/z,ut=U-K*I,ot=D-Q*I,j=B-K*G,pt=L-Q*G,_t=Y-K*lt,Tt=k-Q*lt,Mt=_t*pt-Tt*j,Gt=ut*Tt-ot*_t,ee=j*ot-pt*ut;if(s){if(Mt<0||Gt<0||ee<0)return null}else if((Mt<0||Gt<0||ee<0)&&(Mt>0||Gt>0||ee>0))return null;const kt=Mt+Gt+ee;if(kt===0)return null;const oe=nt*(Mt*I+Gt*G+ee*lt);return(kt>0?oe<0:oe>0)?null:this.at(oe/kt,r)}applyMatrix4(t){return this.origin.applyMatrix4(t),this.direction.transformDirection(t),this}equals(t){return t.origin.equals(this.origin)&&t.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}}class ys extends Ir{constructor(t){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new le(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new ws,this.combine=Af,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.specularMap=t.specularMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.combine=t.combine,this.reflectivity=t.reflectivity,this.refractionRatio=t.refractionRatio,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.fog=t.fog,this}}const Cu=new Le,Us=new Oo,Wa=new Ta,Pu=new V,Xa=new V,$a=new V,Ya=new V,Dl=new V,qa=new V,Lu=new V,Ka=new V;class bn extends Tn{constructor(t=new ln,e=new ys){super(),this.isMesh=!0,this.type="Mesh",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}updateMorphTargets(){const e=this.geometry.morphAttributes,i=Object.keys(e);if(i.length>0){const s=e[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}getVertexPosition(t,e){const i=this.geometry,s=i.attributes.position,r=i.morphAttributes.position,a=i.morphTargetsRelative;e.fromBufferAttribute(s,t);const o=this.morphTargetInfluences;if(r&&o){qa.set(0,0,0);for(let c=0,l=r.length;c<l;c++){const h=o[c],d=r[c];h!==0&&(Dl.fromBufferAttribute(d,t),a?qa.addScaledVector(Dl,h):qa.addScaledVector(Dl.sub(e),h))}e.add(qa)}return e}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){const i=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(i.boundingSphere===null&&i.computeBoundingSphere(),Wa.copy(i.boundingSphere),Wa.applyMatrix4(r),Us.copy(t.ray).recast(t.near),!(Wa.containsPoint(Us.origin)===!1&&(Us.intersectSphere(Wa,Pu)===null||Us.origin.distanceToSquared(Pu)>(t.far-t.near)**2))&&(Cu.copy(r).invert(),Us.copy(t.ray).applyMatrix4(Cu),!(i.boundingBox!==null&&Us.intersectsBox(i.boundingBox)===!1)&&this._computeIntersections(t,e,Us)))}_computeIntersections(t,e,i){let s;const r=this.geometry,a=this.material,o=r.index,c=r.attributes.position,l=r.attributes.uv,h=r.attributes.uv1,d=r.attributes.normal,u=r.groups,m=r.drawRange;if(o!==null)if(Array.isArray(a))for(let v=0,M=u.length;v<M;v++){const p=u[v],f=a[p.materialIndex],x=Math.max(p.start,m.start),A=Math.min(o.count,Math.min(p.start+p.count,m.start+m.count));for(let y=x,R=A;y<R;y+=3){const E=o.getX(y),g=o.getX(y+1),T=o.getX(y+2);s=Za(this,f,t,i,l,h,d,E,g,T),s&&(s.faceIndex=Math.floor(y/3),s.face.materialIndex=p.materialIndex,e.push(s))}}else{const v=Math.max(0,m.start),M=Math.min(o.count,m.start+m.count);for(let p=v,f=M;p<f;p+=3){const x=o.getX(p),A=o.getX(p+1),y=o.getX(p+2);s=Za(this,a,t,i,l,h,d,x,A,y),s&&(s.faceIndex=Math.floor(p/3),e.push(s))}}else if(c!==void 0)if(Array.isArray(a))for(let v=0,M=u.length;v<M;v++){const p=u[v],f=a[p.materialIndex],x=Math.max(p.start,m.start),A=Math.min(c.count,Math.min(p.start+p.count,m.start+m.count));for(let y=x,R=A;y<R;y+=3){const E=y,g=y+1,T=y+2;s=Za(this,f,t,i,l,h,d,E,g,T),s&&(s.faceIndex=Math.floor(y/3),s.face.materialIndex=p.materialIndex,e.push(s))}}else{const v=Math.max(0,m.start),M=Math.min(c.count,m.start+m.count);for(let p=v,f=M;p<f;p+=3){const x=p,A=p+1,y=p+2;s=Za(this,a,t,i,l,h,d,x,A,y),s&&(s.faceIndex=Math.floor(p/3),e.push(s))}}}}function o_(n,t,e,i,s,r,a,o){let c;if(t.side===Vn?c=i.intersectTriangle(a,r,s,!0,o):c=i.intersectTriangle(s,r,a,t.side===Es,o),c===null)return null;Ka.copy(o),Ka.applyMatrix4(n.matrixWorld);const l=e.ray.origin.distanceTo(Ka);return l<e.near||l>e.far?null:{distance:l,point:Ka.clone(),object:n}}function Za(n,t,e,i,s,r,a,o,c,l){n.getVertexPosition(o,Xa),n.getVertexPosition(c,$a),n.getVertexPosition(l,Ya);const h=o_(n,t,e,i,Xa,$a,Ya,Lu);if(h){const d=new V;Mi.getBarycoord(Lu,Xa,$a,Ya,d),s&&(h.uv=Mi.getInterpolatedAttribute(s,o,c,l,d,new Jt)),r&&(h.uv1=Mi.getInterpolatedAttribute(r,o,c,l,d,new Jt)),a&&(h.normal=Mi.getInterpolatedAttribute(a,o,c,l,d,new V),h.normal.dot(i.direction)>0&&h.normal.multiplyScalar(-1));const u={a:o,b:c,c:l,normal:new V,materialIndex:0};Mi.getNormal(Xa,$a,Ya,u.normal),h.face=u,h.barycoord=d}return h}class l_ extends Hn{constructor(t=null,e=1,i=1,s,r,a,o,c,l=wn,h=wn,d,u){super(null,a,o,c,l,h,s,r,d,u),this.isDataTexture=!0,this.image={data:t,width:e,height:i},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}}const Fs=new Ta,c_=new Jt(.5,.5),Ja=new V;class Sa{constructor(t=new Si,e=new Si,i=new Si,s=new Si,r=new Si,a=new Si){this.planes=[t,e,i,s,r,a]}set(t,e,i,s,r,a){const o=this.planes;return o[0].copy(t),o[1].copy(e),o[2].copy(i),o[3].copy(s),o[4].copy(r),o[5].copy(a),this}copy(t){const e=this.planes;for(let i=0;i<6;i++)e[i].copy(t.planes[i]);return this}setFromProjectionMatrix(t,e=bi,i=!1){const s=this.planes,r=t.elements,a=r[0],o=r[1],c=r[2],l=r[3],h=r[4],d=r[5],u=r[6],m=r[7],v=r[8],M=r[9],p=r[10],f=r[11],x=r[12],A=r[13],y=r[14],R=r[15];if(s[0].setComponents(l-a,m-h,f-v,R-x).normalize(),s[1].setComponents(l+a,m+h,f+v,R+x).normalize(),s[2].setComponents(l+o,m+d,f+M,R+A).normalize(),s[3].setComponents(l-o,m-d,f-M,R-A).normalize(),i)s[4].setComponents(c,u,p,y).normalize(),s[5].setComponents(l-c,m-u,f-p,R-y).normalize();else if(s[4].setComponents(l-c,m-u,f-p,R-y).normalize(),e===bi)s[5].setComponents(l+c,m+u,f+p,R+y).normalize();else if(e===xa)s[5].setComponents(c,u,p,y).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+e);return this}intersectsObject(t){if(t.boundingSphere!==void 0)t.boundingSphere===null&&t.computeBoundingSphere(),Fs.copy(t.boundingSphere).applyMatrix4(t.matrixWorld);else{const e=t.geometry;e.boundingSphere===null&&e.computeBoundingSphere(),Fs.copy(e.boundingSphere).applyMatrix4(t.matrixWorld)}return this.intersectsSphere(Fs)}intersectsSprite(t){Fs.center.set(0,0,0);const e=c_.distanceTo(t.center);return Fs.radius=.7071067811865476+e,Fs.applyMatrix4(t.matrixWorld),this.intersectsSphere(Fs)}intersectsSphere(t){const e=this.planes,i=t.center,s=-t.radius;for(let r=0;r<6;r++)if(e[r].distanceToPoint(i)<s)return!1;return!0}intersectsBox(t){const e=this.planes;for(let i=0;i<6;i++){const s=e[i];if(Ja.x=s.normal.x>0?t.max.x:t.min.x,Ja.y=s.normal.y>0?t.max.y:t.min.y,Ja.z=s.normal.z>0?t.max.z:t.min.z,s.distanceToPoint(Ja)<0)return!1}return!0}containsPoint(t){const e=this.planes;for(let i=0;i<6;i++)if(e[i].distanceToPoint(t)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}}const Du=new Le;class bh{constructor(){this.coordinateSystem=bi,this._frustums=[],this._count=0}setFromArrayCamera(t){const e=t.cameras,i=this._frustums;for(let s=0;s<e.length;s++){const r=e[s];Du.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),i[s]===void 0&&(i[s]=new Sa),i[s].setFromProjectionMatrix(Du,r.coordinateSystem,r.reversedDepth)}return this._count=e.length,this}getFrustum(t){return this._frustums[t]}intersectsObject(t){const e=this._frustums;for(let i=0;i<this._count;i++)if(e[i].intersectsObject(t))return!0;return!1}intersectsSprite(t){const e=this._frustums;for(let i=0;i<this._count;i++)if(e[i].intersectsSprite(t))return!0;return!1}intersectsSphere(t){const e=this._frustums;for(let i=0;i<this._count;i++)if(e[i].intersectsSphere(t))return!0;return!1}intersectsBox(t){const e=this._frustums;for(let i=0;i<this._count;i++)if(e[i].intersectsBox(t))return!0;return!1}containsPoint(t){const e=this._frustums;for(let i=0;i<this._count;i++)if(e[i].containsPoint(t))return!0;return!1}copy(t){this.coordinateSystem=t.coordinateSystem;const e=this._frustums,i=t._frustums;for(let s=0;s<t._count;s++)e[s]===void 0&&(e[s]=new Sa),e[s].copy(i[s]);return this._count=t._count,this}clone(){return new bh().copy(this)}}class Ts extends Ir{constructor(t){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new le(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.linewidth=t.linewidth,this.linecap=t.linecap,this.linejoin=t.linejoin,this.fog=t.fog,this}}const Lo=new V,Do=new V,Nu=new Le,Jr=new Oo,Qa=new Ta,Nl=new V,Iu=new V;class Xs extends Tn{constructor(t=new ln,e=new Ts){super(),this.isLine=!0,this.type="Line",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}computeLineDistances(){const t=this.geometry;if(t.index===null){const e=t.attributes.position,i=[0];for(let s=1,r=e.count;s<r;s++)Lo.fromBufferAttribute(e,s-1),Do.fromBufferAttribute(e,s),i[s]=i[s-1],i[s]+=Lo.distanceTo(Do);t.setAttribute("lineDistance",new We(i,1))}else Kt("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){const i=this.geometry,s=this.matrixWorld,r=t.params.Line.threshold,a=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),Qa.copy(i.boundingSphere),Qa.applyMatrix4(s),Qa.radius+=r,t.ray.intersectsSphere(Qa)===!1)return;Nu.copy(s).invert(),Jr.copy(t.ray).applyMatrix4(Nu);const o=r/((this.scale.x+this.scale.y+this.scale.z)/3),c=o*o,l=this.isLineSegments?2:1,h=i.index,u=i.attributes.position;if(h!==null){const m=Math.max(0,a.start),v=Math.min(h.count,a.start+a.count);for(let M=m,p=v-1;M<p;M+=l){const f=h.getX(M),x=h.getX(M+1),A=ja(this,t,Jr,c,f,x,M);A&&e.push(A)}if(this.isLineLoop){const M=h.getX(v-1),p=h.getX(m),f=ja(this,t,Jr,c,M,p,v-1);f&&e.push(f)}}else{const m=Math.max(0,a.start),v=Math.min(u.count,a.start+a.count);for(let M=m,p=v-1;M<p;M+=l){const f=ja(this,t,Jr,c,M,M+1,M);f&&e.push(f)}if(this.isLineLoop){const M=ja(this,t,Jr,c,v-1,m,v-1);M&&e.push(M)}}}updateMorphTargets(){const e=this.geometry.morphAttributes,i=Object.keys(e);if(i.length>0){const s=e[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,a=s.length;r<a;r++){const o=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=r}}}}}function ja(n,t,e,i,s,r,a){const o=n.geometry.attributes.position;if(Lo.fromBufferAttribute(o,s),Do.fromBufferAttribute(o,r),e.distanceSqToSegment(Lo,Do,Nl,Iu)>i)return;Nl.applyMatrix4(n.matrixWorld);const l=t.ray.origin.distanceTo(Nl);if(!(l<t.near||l>t.far))return{distance:l,point:Iu.clone().applyMatrix4(n.matrixWorld),index:a,face:null,faceIndex:null,barycoord:null,object:n}}const Uu=new V,Fu=new V;class h_ extends Xs{constructor(t,e){super(t,e),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){const t=this.geometry;if(t.index===null){const e=t.attributes.position,i=[];for(let s=0,r=e.count;s<r;s+=2)Uu.fromBufferAttribute(e,s),Fu.fromBufferAttribute(e,s+1),i[s]=s===0?0:i[s-1],i[s+1]=i[s]+Uu.distanceTo(Fu);t.setAttribute("lineDistance",new We(i,1))}else Kt("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}}class u_ extends Xs{constructor(t,e){super(t,e),this.isLineLoop=!0,this.type="LineLoop"}}class Qf extends Hn{constructor(t=[],e=Tr,i,s,r,a,o,c,l,h){super(t,e,i,s,r,a,o,c,l,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(t){this.image=t}}class Rr extends Hn{constructor(t,e,i=ki,s,r,a,o=wn,c=wn,l,h=bs,d=1){if(h!==bs&&h!==Ms)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");const u={width:t,height:e,depth:d};super(u,s,r,a,o,c,h,i,l),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(t){return super.copy(t),this.source=new yh(Object.assign({},t.image)),this.compareFunction=t.compareFunction,this}toJSON(t){const e=super.toJSON(t);return e.compareFunction=this.compareFunction,e}}class jf extends Rr{constructor(t,e=ki,i=Tr,s,r,a=wn,o=wn,c,l=bs){const h={width:t,height:t,depth:1},d=[h,h,h,h,h,h];super(t,t,e,i,s,r,a,o,c,l),this.image=d,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(t){this.image=t}}class tp extends Hn{constructor(t=null){super(),this.sourceTexture=t,this.isExternalTexture=!0}copy(t){return super.copy(t),this.sourceTexture=t.sourceTexture,this}}class Aa extends ln{constructor(t=1,e=1,i=1,s=1,r=1,a=1){super(),this.type="BoxGeometry",this.parameters={width:t,height:e,depth:i,widthSegments:s,heightSegments:r,depthSegments:a};const o=this;s=Math.floor(s),r=Math.floor(r),a=Math.floor(a);const c=[],l=[],h=[],d=[];let u=0,m=0;v("z","y","x",-1,-1,i,e,t,a,r,0),v("z","y","x",1,-1,i,e,-t,a,r,1),v("x","z","y",1,1,t,i,e,s,a,2),v("x","z","y",1,-1,t,i,-e,s,a,3),v("x","y","z",1,-1,t,e,i,s,r,4),v("x","y","z",-1,-1,t,e,-i,s,r,5),this.setIndex(c),this.setAttribute("position",new We(l,3)),this.setAttribute("normal",new We(h,3)),this.setAttribute("uv",new We(d,2));function v(M,p,f,x,A,y,R,E,g,T,z){const U=y/g,D=R/T,I=y/2,B=R/2,L=E/2,G=g+1,Y=T+1;let k=0,lt=0;const K=new V;for(let Q=0;Q<Y;Q++){const nt=Q*D-B;for(let ut=0;ut<G;ut++){const ot=ut*U-I;K[M]=ot*x,K[p]=nt*A,K[f]=L,l.push(K.x,K.y,K.z),K[M]=0,K[p]=0,K[f]=E>0?1:-1,h.push(K.x,K.y,K.z),d.push(ut/g),d.push(1-Q/T),k+=1}}for(let Q=0;Q<T;Q++)for(let nt=0;nt<g;nt++){const ut=u+nt+G*Q,ot=u+nt+G*(Q+1),j=u+(nt+1)+G*(Q+1),pt=u+(nt+1)+G*Q;c.push(ut,ot,pt),c.push(ot,j,pt),lt+=6}o.addGroup(m,lt,z),m+=lt,u+=k}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new Aa(t.width,t.height,t.depth,t.widthSegments,t.heightSegments,t.depthSegments)}}class Bo extends ln{constructor(t=1,e=1,i=1,s=32,r=1,a=!1,o=0,c=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:t,radiusBottom:e,height:i,radialSegments:s,heightSegments:r,openEnded:a,thetaStart:o,thetaLength:c};const l=this;s=Math.floor(s),r=Math.floor(r);const h=[],d=[],u=[],m=[];let v=0;const M=[],p=i/2;let f=0;x(),a===!1&&(t>0&&A(!0),e>0&&A(!1)),this.setIndex(h),this.setAttribute("position",new We(d,3)),this.setAttribute("normal",new We(u,3)),this.setAttribute("uv",new We(m,2));function x(){const y=new V,R=new V;let E=0;const g=(e-t)/i;for(let T=0;T<=r;T++){const z=[],U=T/r,D=U*(e-t)+t;for(let I=0;I<=s;I++){const B=I/s,L=B*c+o,G=Math.sin(L),Y=Math.cos(L);R.x=D*G,R.y=-U*i+p,R.z=D*Y,d.push(R.x,R.y,R.z),y.set(G,g,Y).normalize(),u.push(y.x,y.y,y.z),m.push(B,1-U),z.push(v++)}M.push(z)}for(let T=0;T<s;T++)for(let z=0;z<r;z++){const U=M[z][T],D=M[z+1][T],I=M[z+1][T+1],B=M[z][T+1];(t>0||z!==0)&&(h.push(U,D,B),E+=3),(e>0||z!==r-1)&&(h.push(D,I,B),E+=3)}l.addGroup(f,E,0),f+=E}function A(y){const R=v,E=new Jt,g=new V;let T=0;const z=y===!0?t:e,U=y===!0?1:-1;for(let I=1;I<=s;I++)d.push(0,p*U,0),u.push(0,U,0),m.push(.5,.5),v++;const D=v;for(let I=0;I<=s;I++){const L=I/s*c+o,G=Math.cos(L),Y=Math.sin(L);g.x=z*Y,g.y=p*U,g.z=z*G,d.push(g.x,g.y,g.z),u.push(0,U,0),E.x=G*.5+.5,E.y=Y*.5*U+.5,m.push(E.x,E.y),v++}for(let I=0;I<s;I++){const B=R+I,L=D+I;y===!0?h.push(L,L+1,B):h.push(L+1,L,B),T+=3}l.addGroup(f,T,y===!0?1:2),f+=T}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new Bo(t.radiusTop,t.radiusBottom,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}}class wh extends Bo{constructor(t=1,e=1,i=32,s=1,r=!1,a=0,o=Math.PI*2){super(0,t,e,i,s,r,a,o),this.type="ConeGeometry",this.parameters={radius:t,height:e,radialSegments:i,heightSegments:s,openEnded:r,thetaStart:a,thetaLength:o}}static fromJSON(t){return new wh(t.radius,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}}class zo extends ln{constructor(t=1,e=1,i=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:t,height:e,widthSegments:i,heightSegments:s};const r=t/2,a=e/2,o=Math.floor(i),c=Math.floor(s),l=o+1,h=c+1,d=t/o,u=e/c,m=[],v=[],M=[],p=[];for(let f=0;f<h;f++){const x=f*u-a;for(let A=0;A<l;A++){const y=A*d-r;v.push(y,-x,0),M.push(0,0,1),p.push(A/o),p.push(1-f/c)}}for(let f=0;f<c;f++)for(let x=0;x<o;x++){const A=x+l*f,y=x+l*(f+1),R=x+1+l*(f+1),E=x+1+l*f;m.push(A,y,E),m.push(y,R,E)}this.setIndex(m),this.setAttribute("position",new We(v,3)),this.setAttribute("normal",new We(M,3)),this.setAttribute("uv",new We(p,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new zo(t.width,t.height,t.widthSegments,t.heightSegments)}}class Gs extends ln{constructor(t=1,e=32,i=16,s=0,r=Math.PI*2,a=0,o=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:t,widthSegments:e,heightSegments:i,phiStart:s,phiLength:r,thetaStart:a,thetaLength:o},e=Math.max(3,Math.floor(e)),i=Math.max(2,Math.floor(i));const c=Math.min(a+o,Math.PI);let l=0;const h=[],d=new V,u=new V,m=[],v=[],M=[],p=[];for(let f=0;f<=i;f++){const x=[],A=f/i,y=a+A*o,R=t*Math.cos(y),E=Math.sqrt(t*t-R*R);let g=0;f===0&&a===0?g=.5/e:f===i&&c===Math.PI&&(g=-.5/e);for(let T=0;T<=e;T++){const z=T/e,U=s+z*r;d.x=-E*Math.cos(U),d.y=R,d.z=E*Math.sin(U),v.push(d.x,d.y,d.z),u.copy(d).normalize(),M.push(u.x,u.y,u.z),p.push(z+g,1-A),x.push(l++)}h.push(x)}for(let f=0;f<i;f++)for(let x=0;x<e;x++){const A=h[f][x+1],y=h[f][x],R=h[f+1][x],E=h[f+1][x+1];(f!==0||a>0)&&m.push(A,y,E),(f!==i-1||c<Math.PI)&&m.push(y,R,E)}this.setIndex(m),this.setAttribute("position",new We(v,3)),this.setAttribute("normal",new We(M,3)),this.setAttribute("uv",new We(p,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new Gs(t.radius,t.widthSegments,t.heightSegments,t.phiStart,t.phiLength,t.thetaStart,t.thetaLength)}}function Cr(n){const t={};for(const e in n){t[e]={};for(const i in n[e]){const s=n[e][i];if(Ou(s))s.isRenderTargetTexture?(Kt("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),t[e][i]=null):t[e][i]=s.clone();else if(Array.isArray(s))if(Ou(s[0])){const r=[];for(let a=0,o=s.length;a<o;a++)r[a]=s[a].clone();t[e][i]=r}else t[e][i]=s.slice();else t[e][i]=s}}return t}function Bn(n){const t={};for(let e=0;e<n.length;e++){const i=Cr(n[e]);for(const s in i)t[s]=i[s]}return t}function Ou(n){return n&&(n.isColor||n.isMatrix3||n.isMatrix4||n.isVector2||n.isVector3||n.isVector4||n.isTexture||n.isQuaternion)}function d_(n){const t=[];for(let e=0;e<n.length;e++)t.push(n[e].clone());return t}function ep(n){const t=n.getRenderTarget();return t===null?n.outputColorSpace:t.isXRRenderTarget===!0?t.texture.colorSpace:me.workingColorSpace}const f_={clone:Cr,merge:Bn};var p_=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,m_=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`;class As extends Ir{constructor(t){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=p_,this.fragmentShader=m_,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,t!==void 0&&this.setValues(t)}copy(t){return super.copy(t),this.fragmentShader=t.fragmentShader,this.vertexShader=t.vertexShader,this.uniforms=Cr(t.uniforms),this.uniformsGroups=d_(t.uniformsGroups),this.defines=Object.assign({},t.defines),this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.fog=t.fog,this.lights=t.lights,this.clipping=t.clipping,this.extensions=Object.assign({},t.extensions),this.glslVersion=t.glslVersion,this.defaultAttributeValues=Object.assign({},t.defaultAttributeValues),this.index0AttributeName=t.index0AttributeName,this.uniformsNeedUpdate=t.uniformsNeedUpdate,this}toJSON(t){const e=super.toJSON(t);e.glslVersion=this.glslVersion,e.uniforms={};for(const s in this.uniforms){const a=this.uniforms[s].value;a&&a.isTexture?e.uniforms[s]={type:"t",value:a.toJSON(t).uuid}:a&&a.isColor?e.uniforms[s]={type:"c",value:a.getHex()}:a&&a.isVector2?e.uniforms[s]={type:"v2",value:a.toArray()}:a&&a.isVector3?e.uniforms[s]={type:"v3",value:a.toArray()}:a&&a.isVector4?e.uniforms[s]={type:"v4",value:a.toArray()}:a&&a.isMatrix3?e.uniforms[s]={type:"m3",value:a.toArray()}:a&&a.isMatrix4?e.uniforms[s]={type:"m4",value:a.toArray()}:e.uniforms[s]={value:a}}Object.keys(this.defines).length>0&&(e.defines=this.defines),e.vertexShader=this.vertexShader,e.fragmentShader=this.fragmentShader,e.lights=this.lights,e.clipping=this.clipping;const i={};for(const s in this.extensions)this.extensions[s]===!0&&(i[s]=!0);return Object.keys(i).length>0&&(e.extensions=i),e}fromJSON(t,e){if(super.fromJSON(t,e),t.uniforms!==void 0)for(const i in t.uniforms){const s=t.uniforms[i];switch(this.uniforms[i]={},s.type){case"t":this.uniforms[i].value=e[s.value]||null;break;case"c":this.uniforms[i].value=new le().setHex(s.value);break;case"v2":this.uniforms[i].value=new Jt().fromArray(s.value);break;case"v3":this.uniforms[i].value=new V().fromArray(s.value);break;case"v4":this.uniforms[i].value=new Qe().fromArray(s.value);break;case"m3":this.uniforms[i].value=new te().fromArray(s.value);break;case"m4":this.uniforms[i].value=new Le().fromArray(s.value);break;default:this.uniforms[i].value=s.value}}if(t.defines!==void 0&&(this.defines=t.defines),t.vertexShader!==void 0&&(this.vertexShader=t.vertexShader),t.fragmentShader!==void 0&&(this.fragmentShader=t.fragmentShader),t.glslVersion!==void 0&&(this.glslVersion=t.glslVersion),t.extensions!==void 0)for(const i in t.extensions)this.extensions[i]=t.extensions[i];return t.lights!==void 0&&(this.lights=t.lights),t.clipping!==void 0&&(this.clipping=t.clipping),this}}class g_ extends As{constructor(t){super(t),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}}class Il extends Ir{constructor(t){super(),this.isMeshStandardMaterial=!0,this.type="MeshStandardMaterial",this.defines={STANDARD:""},this.color=new le(16777215),this.roughness=1,this.metalness=0,this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new le(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=Yc,this.normalScale=new Jt(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.roughnessMap=null,this.metalnessMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new ws,this.envMapIntensity=1,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.defines={STANDARD:""},this.color.copy(t.color),this.roughness=t.roughness,this.metalness=t.metalness,this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.emissive.copy(t.emissive),this.emissiveMap=t.emissiveMap,this.emissiveIntensity=t.emissiveIntensity,this.bumpMap=t.bumpMap,this.bumpScale=t.bumpScale,this.normalMap=t.normalMap,this.normalMapType=t.normalMapType,this.normalScale.copy(t.normalScale),this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.roughnessMap=t.roughnessMap,this.metalnessMap=t.metalnessMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.envMapIntensity=t.envMapIntensity,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.flatShading=t.flatShading,this.fog=t.fog,this}}class __ extends Ir{constructor(t){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=wg,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(t)}copy(t){return super.copy(t),this.depthPacking=t.depthPacking,this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this}}class v_ extends Ir{constructor(t){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(t)}copy(t){return super.copy(t),this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this}}class x_ extends Ts{constructor(t){super(),this.isLineDashedMaterial=!0,this.type="LineDashedMaterial",this.scale=1,this.dashSize=3,this.gapSize=1,this.setValues(t)}copy(t){return super.copy(t),this.scale=t.scale,this.dashSize=t.dashSize,this.gapSize=t.gapSize,this}}class np extends Tn{static registerNode(t){this.prototype._lightNode=t}constructor(t,e=1){super(),this.isLight=!0,this.type="Light",this.color=new le(t),this.intensity=e}copy(t,e){return super.copy(t,e),this.color.copy(t.color),this.intensity=t.intensity,this}toJSON(t){const e=super.toJSON(t);return e.object.color=this.color.getHex(),e.object.intensity=this.intensity,e}}const Ul=new Le,Bu=new V,zu=new V;class S_{constructor(t){this.camera=t,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new Jt(512,512),this.mapType=Jn,this.map=null,this.mapPass=null,this.matrix=new Le,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new Sa,this._frameExtents=new Jt(1,1),this._viewportCount=1,this._viewports=[new Qe(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(t){const e=this.camera;Bu.setFromMatrixPosition(t.matrixWorld),e.position.copy(Bu),zu.setFromMatrixPosition(t.target.matrixWorld),e.lookAt(zu),e.updateMatrixWorld(),this._updateMatrix(e,this.matrix,this._frustum)}_updateMatrix(t,e,i,s){Ul.multiplyMatrices(t.projectionMatrix,t.matrixWorldInverse),i.setFromProjectionMatrix(Ul,t.coordinateSystem,t.reversedDepth);const r=this._frameExtents,a=s?s.z/r.x:1,o=s?s.w/r.y:1,c=s?s.x/r.x:0,l=s?s.y/r.y:0;t.coordinateSystem===xa||t.reversedDepth?e.set(.5*a,0,0,.5*a+c,0,.5*o,0,.5*o+l,0,0,1,0,0,0,0,1):e.set(.5*a,0,0,.5*a+c,0,.5*o,0,.5*o+l,0,0,.5,.5,0,0,0,1),e.multiply(Ul)}getViewport(t){return this._viewports[t]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(t){return this.camera=t.camera.clone(),this.intensity=t.intensity,this.bias=t.bias,this.radius=t.radius,this.autoUpdate=t.autoUpdate,this.needsUpdate=t.needsUpdate,this.normalBias=t.normalBias,this.blurSamples=t.blurSamples,this.mapSize.copy(t.mapSize),this.mapType=t.mapType,this.biasNode=t.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){const t={};return t.intensity=this.intensity,t.bias=this.bias,t.normalBias=this.normalBias,t.radius=this.radius,t.blurSamples=this.blurSamples,t.mapSize=this.mapSize.toArray(),t.mapType=this.mapType,t.camera=this.camera.toJSON(!1).object,delete t.camera.matrix,t}}const to=new V,eo=new rs,Ni=new V;class ip extends Tn{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new Le,this.projectionMatrix=new Le,this.projectionMatrixInverse=new Le,this.coordinateSystem=bi,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(t,e){return super.copy(t,e),this.matrixWorldInverse.copy(t.matrixWorldInverse),this.projectionMatrix.copy(t.projectionMatrix),this.projectionMatrixInverse.copy(t.projectionMatrixInverse),this.coordinateSystem=t.coordinateSystem,this}getWorldDirection(t){return super.getWorldDirection(t).negate()}updateMatrixWorld(t){super.updateMatrixWorld(t),this.matrixWorld.decompose(to,eo,Ni),Ni.x===1&&Ni.y===1&&Ni.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(to,eo,Ni.set(1,1,1)).invert()}updateWorldMatrix(t,e,i=!1){super.updateWorldMatrix(t,e,i),this.matrixWorld.decompose(to,eo,Ni),Ni.x===1&&Ni.y===1&&Ni.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(to,eo,Ni.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}}const gs=new V,ku=new Jt,Hu=new Jt;class Ln extends ip{constructor(t=50,e=1,i=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=t,this.zoom=1,this.near=i,this.far=s,this.focus=10,this.aspect=e,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.fov=t.fov,this.zoom=t.zoom,this.near=t.near,this.far=t.far,this.focus=t.focus,this.aspect=t.aspect,this.view=t.view===null?null:Object.assign({},t.view),this.filmGauge=t.filmGauge,this.filmOffset=t.filmOffset,this}setFocalLength(t){const e=.5*this.getFilmHeight()/t;this.fov=Po*2*Math.atan(e),this.updateProjectionMatrix()}getFocalLength(){const t=Math.tan(ua*.5*this.fov);return .5*this.getFilmHeight()/t}getEffectiveFOV(){return Po*2*Math.atan(Math.tan(ua*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(t,e,i){gs.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),e.set(gs.x,gs.y).multiplyScalar(-t/gs.z),gs.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),i.set(gs.x,gs.y).multiplyScalar(-t/gs.z)}getViewSize(t,e){return this.getViewBounds(t,ku,Hu),e.subVectors(Hu,ku)}setViewOffset(t,e,i,s,r,a){this.aspect=t/e,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const t=this.near;let e=t*Math.tan(ua*.5*this.fov)/this.zoom,i=2*e,s=this.aspect*i,r=-.5*s;const a=this.view;if(this.view!==null&&this.view.enabled){const c=a.fullWidth,l=a.fullHeight;r+=a.offsetX*s/c,e-=a.offsetY*i/l,s*=a.width/c,i*=a.height/l}const o=this.filmOffset;o!==0&&(r+=t*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,e,e-i,t,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){const e=super.toJSON(t);return e.object.fov=this.fov,e.object.zoom=this.zoom,e.object.near=this.near,e.object.far=this.far,e.object.focus=this.focus,e.object.aspect=this.aspect,this.view!==null&&(e.object.view=Object.assign({},this.view)),e.object.filmGauge=this.filmGauge,e.object.filmOffset=this.filmOffset,e}}class Th extends ip{constructor(t=-1,e=1,i=1,s=-1,r=.1,a=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=t,this.right=e,this.top=i,this.bottom=s,this.near=r,this.far=a,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.left=t.left,this.right=t.right,this.top=t.top,this.bottom=t.bottom,this.near=t.near,this.far=t.far,this.zoom=t.zoom,this.view=t.view===null?null:Object.assign({},t.view),this}setViewOffset(t,e,i,s,r,a){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=a,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){const t=(this.right-this.left)/(2*this.zoom),e=(this.top-this.bottom)/(2*this.zoom),i=(this.right+this.left)/2,s=(this.top+this.bottom)/2;let r=i-t,a=i+t,o=s+e,c=s-e;if(this.view!==null&&this.view.enabled){const l=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=l*this.view.offsetX,a=r+l*this.view.width,o-=h*this.view.offsetY,c=o-h*this.view.height}this.projectionMatrix.makeOrthographic(r,a,o,c,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){const e=super.toJSON(t);return e.object.zoom=this.zoom,e.object.left=this.left,e.object.right=this.right,e.object.top=this.top,e.object.bottom=this.bottom,e.object.near=this.near,e.object.far=this.far,this.view!==null&&(e.object.view=Object.assign({},this.view)),e}}class M_ extends S_{constructor(){super(new Th(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}}class y_ extends np{constructor(t,e){super(t,e),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(Tn.DEFAULT_UP),this.updateMatrix(),this.target=new Tn,this.shadow=new M_}dispose(){super.dispose(),this.shadow.dispose()}copy(t){return super.copy(t),this.target=t.target.clone(),this.shadow=t.shadow.clone(),this}toJSON(t){const e=super.toJSON(t);return e.object.shadow=this.shadow.toJSON(),e.object.target=this.target.uuid,e}}class E_ extends np{constructor(t,e){super(t,e),this.isAmbientLight=!0,this.type="AmbientLight"}}const Gu=new Le,Vu=new Le,Os=new Le;class b_{constructor(){this.type="StereoCamera",this.aspect=1,this.eyeSep=.064,this.cameraL=new Ln,this.cameraL.layers.enable(1),this.cameraL.matrixAutoUpdate=!1,this.cameraR=new Ln,this.cameraR.layers.enable(2),this.cameraR.matrixAutoUpdate=!1,this._cache={focus:null,fov:null,aspect:null,near:null,far:null,zoom:null,eyeSep:null}}update(t){const e=this._cache;if(e.focus!==t.focus||e.fov!==t.fov||e.aspect!==t.aspect*this.aspect||e.near!==t.near||e.far!==t.far||e.zoom!==t.zoom||e.eyeSep!==this.eyeSep){e.focus=t.focus,e.fov=t.fov,e.aspect=t.aspect*this.aspect,e.near=t.near,e.far=t.far,e.zoom=t.zoom,e.eyeSep=this.eyeSep,Os.copy(t.projectionMatrix);const s=e.eyeSep/2,r=s*e.near/e.focus,a=e.near*Math.tan(ua*e.fov*.5)/e.zoom;let o,c;Vu.elements[12]=-s,Gu.elements[12]=s,o=-a*e.aspect+r,c=a*e.aspect+r,Os.elements[0]=2*e.near/(c-o),Os.elements[8]=(c+o)/(c-o),this.cameraL.projectionMatrix.copy(Os),o=-a*e.aspect-r,c=a*e.aspect-r,Os.elements[0]=2*e.near/(c-o),Os.elements[8]=(c+o)/(c-o),this.cameraR.projectionMatrix.copy(Os)}this.cameraL.matrix.copy(t.matrixWorld).multiply(Vu),this.cameraL.matrixWorldNeedsUpdate=!0,this.cameraR.matrix.copy(t.matrixWorld).multiply(Gu),this.cameraR.matrixWorldNeedsUpdate=!0}}const mr=-90,gr=1;class qc extends Tn{constructor(t,e,i){super(),this.type="CubeCamera",this.renderTarget=i,this.coordinateSystem=null,this.activeMipmapLevel=0;const s=new Ln(mr,gr,t,e);s.layers=this.layers,this.add(s);const r=new Ln(mr,gr,t,e);r.layers=this.layers,this.add(r);const a=new Ln(mr,gr,t,e);a.layers=this.layers,this.add(a);const o=new Ln(mr,gr,t,e);o.layers=this.layers,this.add(o);const c=new Ln(mr,gr,t,e);c.layers=this.layers,this.add(c);const l=new Ln(mr,gr,t,e);l.layers=this.layers,this.add(l)}updateCoordinateSystem(){const t=this.coordinateSystem,e=this.children.concat(),[i,s,r,a,o,c]=e;for(const l of e)this.remove(l);if(t===bi)i.up.set(0,1,0),i.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),a.up.set(0,0,1),a.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),c.up.set(0,1,0),c.lookAt(0,0,-1);else if(t===xa)i.up.set(0,-1,0),i.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),a.up.set(0,0,-1),a.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),c.up.set(0,-1,0),c.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+t);for(const l of e)this.add(l),l.updateMatrixWorld()}update(t,e){this.parent===null&&this.updateMatrixWorld();const{renderTarget:i,activeMipmapLevel:s}=this;this.coordinateSystem!==t.coordinateSystem&&(this.coordinateSystem=t.coordinateSystem,this.updateCoordinateSystem());const[r,a,o,c,l,h]=this.children,d=t.getRenderTarget(),u=t.getActiveCubeFace(),m=t.getActiveMipmapLevel(),v=t.xr.enabled;t.xr.enabled=!1;const M=i.texture.mipmapsAutoUpdate;i.texture.mipmapsAutoUpdate=!1;let p=!1;t.isWebGLRenderer===!0?p=t.state.buffers.depth.getReversed():p=t.reversedDepthBuffer,t.setRenderTarget(i,0,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,r),t.setRenderTarget(i,1,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,a),t.setRenderTarget(i,2,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,o),t.setRenderTarget(i,3,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,c),t.setRenderTarget(i,4,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,l),i.texture.mipmapsAutoUpdate=M,t.setRenderTarget(i,5,s),p&&t.autoClear===!1&&t.clearDepth(),t.render(e,h),t.setRenderTarget(d,u,m),t.xr.enabled=v,i.texture.needsPMREMUpdate=!0}}class w_ extends Ln{constructor(t=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=t,this.perCameraFrustumCulled=!1}}const Wu=new Le;class sp{constructor(t,e,i=0,s=1/0){this.ray=new Oo(t,e),this.near=i,this.far=s,this.camera=null,this.layers=new Eh,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(t,e){this.ray.set(t,e)}setFromCamera(t,e){e.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(t.x,t.y,.5).unproject(e).sub(this.ray.origin).normalize(),this.camera=e):e.isOrthographicCamera?(this.ray.origin.set(t.x,t.y,e.projectionMatrix.elements[14]).unproject(e),this.ray.direction.set(0,0,-1).transformDirection(e.matrixWorld),this.camera=e):ve("Raycaster: Unsupported camera type: "+e.type)}setFromXRController(t){return Wu.identity().extractRotation(t.matrixWorld),this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4(Wu),this}intersectObject(t,e=!0,i=[]){return Kc(t,this,i,e),i.sort(Xu),i}intersectObjects(t,e=!0,i=[]){for(let s=0,r=t.length;s<r;s++)Kc(t[s],this,i,e);return i.sort(Xu),i}}function Xu(n,t){return n.distance-t.distance}function Kc(n,t,e,i){let s=!0;if(n.layers.test(t.layers)&&n.raycast(t,e)===!1&&(s=!1),s===!0&&i===!0){const r=n.children;for(let a=0,o=r.length;a<o;a++)Kc(r[a],t,e,!0)}}class $u{constructor(t=1,e=0,i=0){this.radius=t,this.phi=e,this.theta=i}set(t,e,i){return this.radius=t,this.phi=e,this.theta=i,this}copy(t){return this.radius=t.radius,this.phi=t.phi,this.theta=t.theta,this}makeSafe(){return this.phi=de(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(t){return this.setFromCartesianCoords(t.x,t.y,t.z)}setFromCartesianCoords(t,e,i){return this.radius=Math.sqrt(t*t+e*e+i*i),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(t,i),this.phi=Math.acos(de(e/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}}const Yu=new V;let no,Fl;class T_ extends Tn{constructor(t=new V(0,0,1),e=new V(0,0,0),i=1,s=16776960,r=i*.2,a=r*.2){super(),this.type="ArrowHelper",no===void 0&&(no=new ln,no.setAttribute("position",new We([0,0,0,0,1,0],3)),Fl=new wh(.5,1,5,1),Fl.translate(0,-.5,0)),this.position.copy(e),this.line=new Xs(no,new Ts({color:s,toneMapped:!1})),this.line.matrixAutoUpdate=!1,this.add(this.line),this.cone=new bn(Fl,new ys({color:s,toneMapped:!1})),this.cone.matrixAutoUpdate=!1,this.add(this.cone),this.setDirection(t),this.setLength(i,r,a)}setDirection(t){if(t.y>.99999)this.quaternion.set(0,0,0,1);else if(t.y<-.99999)this.quaternion.set(1,0,0,0);else{Yu.set(t.z,0,-t.x).normalize();const e=Math.acos(t.y);this.quaternion.setFromAxisAngle(Yu,e)}}setLength(t,e=t*.2,i=e*.2){this.line.scale.set(1,Math.max(1e-4,t-e),1),this.line.updateMatrix(),this.cone.scale.set(i,e,i),this.cone.position.y=t,this.cone.updateMatrix()}setColor(t){this.line.material.color.set(t),this.cone.material.color.set(t)}copy(t){return super.copy(t,!1),this.line.copy(t.line),this.cone.copy(t.cone),this}dispose(){super.dispose(),this.line.geometry.dispose(),this.line.material.dispose(),this.cone.geometry.dispose(),this.cone.material.dispose()}}class rp extends h_{constructor(t=1){const e=[0,0,0,t,0,0,0,0,0,0,t,0,0,0,0,0,0,t],i=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new ln;s.setAttribute("position",new We(e,3)),s.setAttribute("color",new We(i,3));const r=new Ts({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(t,e,i){const s=new le,r=this.geometry.attributes.color.array;return s.set(t),s.toArray(r,0),s.toArray(r,3),s.set(e),s.toArray(r,6),s.toArray(r,9),s.set(i),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}}let A_=class extends Cs{constructor(t,e=null){super(),this.object=t,this.domElement=e,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(t){this.domElement!==null&&this.disconnect(),this.domElement=t}disconnect(){}dispose(){}update(){}};function qu(n,t,e,i){const s=R_(i);switch(e){case kf:return n*t;case Gf:return n*t/s.components*s.byteLength;case _h:return n*t/s.components*s.byteLength;case Ws:return n*t*2/s.components*s.byteLength;case vh:return n*t*2/s.components*s.byteLength;case Hf:return n*t*3/s.components*s.byteLength;case Ei:return n*t*4/s.components*s.byteLength;case xh:return n*t*4/s.components*s.byteLength;case vo:case xo:return Math.floor((n+3)/4)*Math.floor((t+3)/4)*8;case So:case Mo:return Math.floor((n+3)/4)*Math.floor((t+3)/4)*16;case vc:case Sc:return Math.max(n,16)*Math.max(t,8)/4;case _c:case xc:return Math.max(n,8)*Math.max(t,8)/2;case Mc:case yc:case bc:case wc:return Math.floor((n+3)/4)*Math.floor((t+3)/4)*8;case Ec:case wo:case Tc:return Math.floor((n+3)/4)*Math.floor((t+3)/4)*16;case Ac:return Math.floor((n+3)/4)*Math.floor((t+3)/4)*16;case Rc:return Math.floor((n+4)/5)*Math.floor((t+3)/4)*16;case Cc:return Math.floor((n+4)/5)*Math.floor((t+4)/5)*16;case Pc:return Math.floor((n+5)/6)*Math.floor((t+4)/5)*16;case Lc:return Math.floor((n+5)/6)*Math.floor((t+5)/6)*16;case Dc:return Math.floor((n+7)/8)*Math.floor((t+4)/5)*16;case Nc:return Math.floor((n+7)/8)*Math.floor((t+5)/6)*16;case Ic:return Math.floor((n+7)/8)*Math.floor((t+7)/8)*16;case Uc:return Math.floor((n+9)/10)*Math.floor((t+4)/5)*16;case Fc:return Math.floor((n+9)/10)*Math.floor((t+5)/6)*16;case Oc:return Math.floor((n+9)/10)*Math.floor((t+7)/8)*16;case Bc:return Math.floor((n+9)/10)*Math.floor((t+9)/10)*16;case zc:return Math.floor((n+11)/12)*Math.floor((t+9)/10)*16;case kc:return Math.floor((n+11)/12)*Math.floor((t+11)/12)*16;case Hc:case Gc:case Vc:return Math.ceil(n/4)*Math.ceil(t/4)*16;case Wc:case Xc:return Math.ceil(n/4)*Math.ceil(t/4)*8;case To:case $c:return Math.ceil(n/4)*Math.ceil(t/4)*16}throw new Error(`Unable to determine texture byte length for ${e} format.`)}function R_(n){switch(n){case Jn:case Ff:return{byteLength:1,components:1};case va:case Of:case Hi:return{byteLength:2,components:1};case mh:case gh:return{byteLength:2,components:4};case ki:case ph:case Bi:return{byteLength:4,components:1};case Bf:case zf:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${n}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:fh}}));typeof window<"u"&&(window.__THREE__?Kt("WARNING: Multiple instances of Three.js being imported."):window.__THREE__=fh);function ap(){let n=null,t=!1,e=null,i=null;function s(r,a){i=n.requestAnimationFrame(s),e(r,a)}return{start:function(){t!==!0&&e!==null&&n!==null&&(i=n.requestAnimationFrame(s),t=!0)},stop:function(){n!==null&&n.cancelAnimationFrame(i),t=!1},setAnimationLoop:function(r){e=r},setContext:function(r){n=r}}}function C_(n){const t=new WeakMap;function e(o,c){const l=o.array,h=o.usage,d=l.byteLength,u=n.createBuffer();n.bindBuffer(c,u),n.bufferData(c,l,h),o.onUploadCallback();let m;if(l instanceof Float32Array)m=n.FLOAT;else if(typeof Float16Array<"u"&&l instanceof Float16Array)m=n.HALF_FLOAT;else if(l instanceof Uint16Array)o.isFloat16BufferAttribute?m=n.HALF_FLOAT:m=n.UNSIGNED_SHORT;else if(l instanceof Int16Array)m=n.SHORT;else if(l instanceof Uint32Array)m=n.UNSIGNED_INT;else if(l instanceof Int32Array)m=n.INT;else if(l instanceof Int8Array)m=n.BYTE;else if(l instanceof Uint8Array)m=n.UNSIGNED_BYTE;else if(l instanceof Uint8ClampedArray)m=n.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+l);return{buffer:u,type:m,bytesPerElement:l.BYTES_PER_ELEMENT,version:o.version,size:d}}function i(o,c,l){const h=c.array,d=c.updateRanges;if(n.bindBuffer(l,o),d.length===0)n.bufferSubData(l,0,h);else{d.sort((m,v)=>m.start-v.start);let u=0;for(let m=1;m<d.length;m++){const v=d[u],M=d[m];M.start<=v.start+v.count+1?v.count=Math.max(v.count,M.start+M.count-v.start):(++u,d[u]=M)}d.length=u+1;for(let m=0,v=d.length;m<v;m++){const M=d[m];n.bufferSubData(l,M.start*h.BYTES_PER_ELEMENT,h,M.start,M.count)}c.clearUpdateRanges()}c.onUploadCallback()}function s(o){return o.isInterleavedBufferAttribute&&(o=o.data),t.get(o)}function r(o){o.isInterleavedBufferAttribute&&(o=o.data);const c=t.get(o);c&&(n.deleteBuffer(c.buffer),t.delete(o))}function a(o,c){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){const h=t.get(o);(!h||h.version<o.version)&&t.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}const l=t.get(o);if(l===void 0)t.set(o,e(o,c));else if(l.version<o.version){if(l.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");i(l.buffer,o,c),l.version=o.version}}return{get:s,remove:r,update:a}}var P_=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,L_=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,D_=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,N_=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,I_=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,U_=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,F_=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,O_=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,B_=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,z_=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,k_=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,H_=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,G_=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,V_=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,W_=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,X_=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,$_=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,Y_=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,q_=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,K_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,Z_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,J_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,Q_=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,j_=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,t0=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,e0=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,n0=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,i0=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,s0=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,r0="gl_FragColor = linearToOutputTexel( gl_FragColor );",a0=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,o0=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,l0=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,c0=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,h0=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,u0=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,d0=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,f0=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,p0=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,m0=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,g0=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,_0=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,v0=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,x0=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,S0=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,M0=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,y0=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,E0=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,b0=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,w0=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,T0=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,A0=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,R0=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,C0=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,P0=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,L0=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,D0=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,N0=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,I0=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,U0=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,F0=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,O0=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,B0=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,z0=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,k0=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,H0=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,G0=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,V0=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,W0=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,X0=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,$0=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Y0=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,q0=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,K0=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,Z0=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,J0=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,Q0=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,j0=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,tv=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,ev=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,nv=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,iv=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,sv=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,rv=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,av=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,ov=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,lv=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,cv=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,hv=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,uv=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,dv=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,fv=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,pv=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,mv=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,gv=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,_v=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,vv=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,xv=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,Sv=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,Mv=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,yv=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,Ev=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,bv=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,wv=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Tv=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Av=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,Rv=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`;const Cv=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,Pv=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Lv=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Dv=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Nv=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Iv=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Uv=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,Fv=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,Ov=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,Bv=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,zv=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,kv=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Hv=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,Gv=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,Vv=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,Wv=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Xv=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,$v=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Yv=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,qv=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Kv=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,Zv=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,Jv=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,Qv=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,jv=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,tx=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,ex=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,nx=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,ix=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,sx=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,rx=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,ax=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,ox=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,lx=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,ae={alphahash_fragment:P_,alphahash_pars_fragment:L_,alphamap_fragment:D_,alphamap_pars_fragment:N_,alphatest_fragment:I_,alphatest_pars_fragment:U_,aomap_fragment:F_,aomap_pars_fragment:O_,batching_pars_vertex:B_,batching_vertex:z_,begin_vertex:k_,beginnormal_vertex:H_,bsdfs:G_,iridescence_fragment:V_,bumpmap_pars_fragment:W_,clipping_planes_fragment:X_,clipping_planes_pars_fragment:$_,clipping_planes_pars_vertex:Y_,clipping_planes_vertex:q_,color_fragment:K_,color_pars_fragment:Z_,color_pars_vertex:J_,color_vertex:Q_,common:j_,defaultnormal_vertex:t0,displacementmap_pars_vertex:e0,displacementmap_vertex:n0,emissivemap_fragment:i0,emissivemap_pars_fragment:s0,colorspace_fragment:r0,colorspace_pars_fragment:a0,envmap_fragment:o0,envmap_common_pars_fragment:l0,envmap_pars_fragment:c0,envmap_pars_vertex:h0,envmap_physical_pars_fragment:M0,envmap_vertex:u0,fog_vertex:d0,fog_pars_vertex:f0,fog_fragment:p0,fog_pars_fragment:m0,gradientmap_pars_fragment:g0,lightmap_pars_fragment:_0,lights_lambert_fragment:v0,lights_lambert_pars_fragment:x0,lights_pars_begin:S0,lights_toon_fragment:y0,lights_toon_pars_fragment:E0,lights_phong_fragment:b0,lights_phong_pars_fragment:w0,lights_physical_fragment:T0,lights_physical_pars_fragment:A0,lights_fragment_begin:R0,lights_fragment_maps:C0,lights_fragment_end:P0,lightprobes_pars_fragment:L0,logdepthbuf_fragment:D0,logdepthbuf_pars_fragment:N0,logdepthbuf_pars_vertex:I0,logdepthbuf_vertex:U0,map_fragment:F0,map_pars_fragment:O0,map_particle_fragment:B0,map_particle_pars_fragment:z0,metalnessmap_fragment:k0,metalnessmap_pars_fragment:H0,morphinstance_vertex:G0,morphcolor_vertex:V0,morphnormal_vertex:W0,morphtarget_pars_vertex:X0,morphtarget_vertex:$0,normal_fragment_begin:Y0,normal_fragment_maps:q0,normal_pars_fragment:K0,normal_pars_vertex:Z0,normal_vertex:J0,normalmap_pars_fragment:Q0,clearcoat_normal_fragment_begin:j0,clearcoat_normal_fragment_maps:tv,clearcoat_pars_fragment:ev,iridescence_pars_fragment:nv,opaque_fragment:iv,packing:sv,premultiplied_alpha_fragment:rv,project_vertex:av,dithering_fragment:ov,dithering_pars_fragment:lv,roughnessmap_fragment:cv,roughnessmap_pars_fragment:hv,shadowmap_pars_fragment:uv,shadowmap_pars_vertex:dv,shadowmap_vertex:fv,shadowmask_pars_fragment:pv,skinbase_vertex:mv,skinning_pars_vertex:gv,skinning_vertex:_v,skinnormal_vertex:vv,specularmap_fragment:xv,specularmap_pars_fragment:Sv,tonemapping_fragment:Mv,tonemapping_pars_fragment:yv,transmission_fragment:Ev,transmission_pars_fragment:bv,uv_pars_fragment:wv,uv_pars_vertex:Tv,uv_vertex:Av,worldpos_vertex:Rv,background_vert:Cv,background_frag:Pv,backgroundCube_vert:Lv,backgroundCube_frag:Dv,cube_vert:Nv,cube_frag:Iv,depth_vert:Uv,depth_frag:Fv,distance_vert:Ov,distance_frag:Bv,equirect_vert:zv,equirect_frag:kv,linedashed_vert:Hv,linedashed_frag:Gv,meshbasic_vert:Vv,meshbasic_frag:Wv,meshlambert_vert:Xv,meshlambert_frag:$v,meshmatcap_vert:Yv,meshmatcap_frag:qv,meshnormal_vert:Kv,meshnormal_frag:Zv,meshphong_vert:Jv,meshphong_frag:Qv,meshphysical_vert:jv,meshphysical_frag:tx,meshtoon_vert:ex,meshtoon_frag:nx,points_vert:ix,points_frag:sx,shadow_vert:rx,shadow_frag:ax,sprite_vert:ox,sprite_frag:lx},Lt={common:{diffuse:{value:new le(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new te},alphaMap:{value:null},alphaMapTransform:{value:new te},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new te}},envmap:{envMap:{value:null},envMapRotation:{value:new te},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new te}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new te}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new te},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new te},normalScale:{value:new Jt(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new te},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new te}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new te}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new te}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new le(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new le(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new te},alphaTest:{value:0},uvTransform:{value:new te}},sprite:{diffuse:{value:new le(16777215)},opacity:{value:1},center:{value:new Jt(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new te},alphaMap:{value:null},alphaMapTransform:{value:new te},alphaTest:{value:0}}},Oi={basic:{uniforms:Bn([Lt.common,Lt.specularmap,Lt.envmap,Lt.aomap,Lt.lightmap,Lt.fog]),vertexShader:ae.meshbasic_vert,fragmentShader:ae.meshbasic_frag},lambert:{uniforms:Bn([Lt.common,Lt.specularmap,Lt.envmap,Lt.aomap,Lt.lightmap,Lt.emissivemap,Lt.bumpmap,Lt.normalmap,Lt.displacementmap,Lt.fog,Lt.lights,{emissive:{value:new le(0)},envMapIntensity:{value:1}}]),vertexShader:ae.meshlambert_vert,fragmentShader:ae.meshlambert_frag},phong:{uniforms:Bn([Lt.common,Lt.specularmap,Lt.envmap,Lt.aomap,Lt.lightmap,Lt.emissivemap,Lt.bumpmap,Lt.normalmap,Lt.displacementmap,Lt.fog,Lt.lights,{emissive:{value:new le(0)},specular:{value:new le(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:ae.meshphong_vert,fragmentShader:ae.meshphong_frag},standard:{uniforms:Bn([Lt.common,Lt.envmap,Lt.aomap,Lt.lightmap,Lt.emissivemap,Lt.bumpmap,Lt.normalmap,Lt.displacementmap,Lt.roughnessmap,Lt.metalnessmap,Lt.fog,Lt.lights,{emissive:{value:new le(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:ae.meshphysical_vert,fragmentShader:ae.meshphysical_frag},toon:{uniforms:Bn([Lt.common,Lt.aomap,Lt.lightmap,Lt.emissivemap,Lt.bumpmap,Lt.normalmap,Lt.displacementmap,Lt.gradientmap,Lt.fog,Lt.lights,{emissive:{value:new le(0)}}]),vertexShader:ae.meshtoon_vert,fragmentShader:ae.meshtoon_frag},matcap:{uniforms:Bn([Lt.common,Lt.bumpmap,Lt.normalmap,Lt.displacementmap,Lt.fog,{matcap:{value:null}}]),vertexShader:ae.meshmatcap_vert,fragmentShader:ae.meshmatcap_frag},points:{uniforms:Bn([Lt.points,Lt.fog]),vertexShader:ae.points_vert,fragmentShader:ae.points_frag},dashed:{uniforms:Bn([Lt.common,Lt.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:ae.linedashed_vert,fragmentShader:ae.linedashed_frag},depth:{uniforms:Bn([Lt.common,Lt.displacementmap]),vertexShader:ae.depth_vert,fragmentShader:ae.depth_frag},normal:{uniforms:Bn([Lt.common,Lt.bumpmap,Lt.normalmap,Lt.displacementmap,{opacity:{value:1}}]),vertexShader:ae.meshnormal_vert,fragmentShader:ae.meshnormal_frag},sprite:{uniforms:Bn([Lt.sprite,Lt.fog]),vertexShader:ae.sprite_vert,fragmentShader:ae.sprite_frag},background:{uniforms:{uvTransform:{value:new te},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:ae.background_vert,fragmentShader:ae.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new te}},vertexShader:ae.backgroundCube_vert,fragmentShader:ae.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:ae.cube_vert,fragmentShader:ae.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:ae.equirect_vert,fragmentShader:ae.equirect_frag},distance:{uniforms:Bn([Lt.common,Lt.displacementmap,{referencePosition:{value:new V},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:ae.distance_vert,fragmentShader:ae.distance_frag},shadow:{uniforms:Bn([Lt.lights,Lt.fog,{color:{value:new le(0)},opacity:{value:1}}]),vertexShader:ae.shadow_vert,fragmentShader:ae.shadow_frag}};Oi.physical={uniforms:Bn([Oi.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new te},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new te},clearcoatNormalScale:{value:new Jt(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new te},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new te},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new te},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new te},sheen:{value:0},sheenColor:{value:new le(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new te},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new te},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new te},transmissionSamplerSize:{value:new Jt},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new te},attenuationDistance:{value:0},attenuationColor:{value:new le(0)},specularColor:{value:new le(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new te},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new te},anisotropyVector:{value:new Jt},anisotropyMap:{value:null},anisotropyMapTransform:{value:new te}}]),vertexShader:ae.meshphysical_vert,fragmentShader:ae.meshphysical_frag};const io={r:0,b:0,g:0},cx=new Le,op=new te;op.set(-1,0,0,0,1,0,0,0,1);function hx(n,t,e,i,s,r){const a=new le(0);let o=s===!0?0:1,c,l,h=null,d=0,u=null;function m(x){let A=x.isScene===!0?x.background:null;if(A&&A.isTexture){const y=x.backgroundBlurriness>0;A=t.get(A,y)}return A}function v(x){let A=!1;const y=m(x);y===null?p(a,o):y&&y.isColor&&(p(y,1),A=!0);const R=n.xr.getEnvironmentBlendMode();R==="additive"?e.buffers.color.setClear(0,0,0,1,r):R==="alpha-blend"&&e.buffers.color.setClear(0,0,0,0,r),(n.autoClear||A)&&(e.buffers.depth.setTest(!0),e.buffers.depth.setMask(!0),e.buffers.color.setMask(!0),n.clear(n.autoClearColor,n.autoClearDepth,n.autoClearStencil))}function M(x,A){const y=m(A);y&&y.isCubeTexture?(l===void 0&&(l=new bn(new Aa(1,1,1),new As({name:"BackgroundCubeMaterial",uniforms:Cr(Oi.backgroundCube.uniforms),vertexShader:Oi.backgroundCube.vertexShader,fragmentShader:Oi.backgroundCube.fragmentShader,side:Vn,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),l.geometry.deleteAttribute("uv"),l.onBeforeRender=function(R,E,g){this.matrixWorld.copyPosition(g.matrixWorld)},Object.defineProperty(l.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),i.update(l)),l.material.uniforms.envMap.value=y,l.material.uniforms.backgroundBlurriness.value=A.backgroundBlurriness,l.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,l.material.uniforms.backgroundRotation.value.setFromMatrix4(cx.makeRotationFromEuler(A.backgroundRotation)).transpose(),y.isRenderTargetTexture===!1&&l.material.uniforms.backgroundRotation.value.premultiply(op),l.material.toneMapped=me.getTransfer(y.colorSpace)!==Ae,(h!==y||d!==y.version||u!==n.toneMapping)&&(l.material.needsUpdate=!0,h=y,d=y.version,u=n.toneMapping),l.layers.enableAll(),x.unshift(l,l.geometry,l.material,0,0,null)):y&&y.isTexture&&(c===void 0&&(c=new bn(new zo(2,2),new As({name:"BackgroundMaterial",uniforms:Cr(Oi.background.uniforms),vertexShader:Oi.background.vertexShader,fragmentShader:Oi.background.fragmentShader,side:Es,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),Object.defineProperty(c.material,"map",{get:function(){return this.uniforms.t2D.value}}),i.update(c)),c.material.uniforms.t2D.value=y,c.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,c.material.toneMapped=me.getTransfer(y.colorSpace)!==Ae,y.matrixAutoUpdate===!0&&y.updateMatrix(),c.material.uniforms.uvTransform.value.copy(y.matrix),(h!==y||d!==y.version||u!==n.toneMapping)&&(c.material.needsUpdate=!0,h=y,d=y.version,u=n.toneMapping),c.layers.enableAll(),x.unshift(c,c.geometry,c.material,0,0,null))}function p(x,A){x.getRGB(io,ep(n)),e.buffers.color.setClear(io.r,io.g,io.b,A,r)}function f(){l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0),c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0)}return{getClearColor:function(){return a},setClearColor:function(x,A=1){a.set(x),o=A,p(a,o)},getClearAlpha:function(){return o},setClearAlpha:function(x){o=x,p(a,o)},render:v,addToRenderList:M,dispose:f}}function ux(n,t){const e=n.getParameter(n.MAX_VERTEX_ATTRIBS),i={},s=u(null);let r=s,a=!1;function o(D,I,B,L,G){let Y=!1;const k=d(D,L,B,I);r!==k&&(r=k,l(r.object)),Y=m(D,L,B,G),Y&&v(D,L,B,G),G!==null&&t.update(G,n.ELEMENT_ARRAY_BUFFER),(Y||a)&&(a=!1,y(D,I,B,L),G!==null&&n.bindBuffer(n.ELEMENT_ARRAY_BUFFER,t.get(G).buffer))}function c(){return n.createVertexArray()}function l(D){return n.bindVertexArray(D)}function h(D){return n.deleteVertexArray(D)}function d(D,I,B,L){const G=L.wireframe===!0;let Y=i[I.id];Y===void 0&&(Y={},i[I.id]=Y);const k=D.isInstancedMesh===!0?D.id:0;let lt=Y[k];lt===void 0&&(lt={},Y[k]=lt);let K=lt[B.id];K===void 0&&(K={},lt[B.id]=K);let Q=K[G];return Q===void 0&&(Q=u(c()),K[G]=Q),Q}function u(D){const I=[],B=[],L=[];for(let G=0;G<e;G++)I[G]=0,B[G]=0,L[G]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:I,enabledAttributes:B,attributeDivisors:L,object:D,attributes:{},index:null}}function m(D,I,B,L){const G=r.attributes,Y=I.attributes;let k=0;const lt=B.getAttributes();for(const K in lt)if(lt[K].location>=0){const nt=G[K];let ut=Y[K];if(ut===void 0&&(K==="instanceMatrix"&&D.instanceMatrix&&(ut=D.instanceMatrix),K==="instanceColor"&&D.instanceColor&&(ut=D.instanceColor)),nt===void 0||nt.attribute!==ut||ut&&nt.data!==ut.data)return!0;k++}return r.attributesNum!==k||r.index!==L}function v(D,I,B,L){const G={},Y=I.attributes;let k=0;const lt=B.getAttributes();for(const K in lt)if(lt[K].location>=0){let nt=Y[K];nt===void 0&&(K==="instanceMatrix"&&D.instanceMatrix&&(nt=D.instanceMatrix),K==="instanceColor"&&D.instanceColor&&(nt=D.instanceColor));const ut={};ut.attribute=nt,nt&&nt.data&&(ut.data=nt.data),G[K]=ut,k++}r.attributes=G,r.attributesNum=k,r.index=L}function M(){const D=r.newAttributes;for(let I=0,B=D.length;I<B;I++)D[I]=0}function p(D){f(D,0)}function f(D,I){const B=r.newAttributes,L=r.enabledAttributes,G=r.attributeDivisors;B[D]=1,L[D]===0&&(n.enableVertexAttribArray(D),L[D]=1),G[D]!==I&&(n.vertexAttribDivisor(D,I),G[D]=I)}function x(){const D=r.newAttributes,I=r.enabledAttributes;for(let B=0,L=I.length;B<L;B++)I[B]!==D[B]&&(n.disableVertexAttribArray(B),I[B]=0)}function A(D,I,B,L,G,Y,k){k===!0?n.vertexAttribIPointer(D,I,B,G,Y):n.vertexAttribPointer(D,I,B,L,G,Y)}function y(D,I,B,L){M();const G=L.attributes,Y=B.getAttributes(),k=I.defaultAttributeValues;for(const lt in Y){const K=Y[lt];if(K.location>=0){let Q=G[lt];if(Q===void 0&&(lt==="instanceMatrix"&&D.instanceMatrix&&(Q=D.instanceMatrix),lt==="instanceColor"&&D.instanceColor&&(Q=D.instanceColor)),Q!==void 0){const nt=Q.normalized,ut=Q.itemSize,ot=t.get(Q);if(ot===void 0)continue;const j=ot.buffer,pt=ot.type,_t=ot.bytesPerElement,Tt=pt===n.INT||pt===n.UNSIGNED_INT||Q.gpuType===ph;if(Q.isInterleavedBufferAttribute){const Mt=Q.data,Gt=Mt.isInterleavedBuffer===!0?Mt.stride:Mt.itemSize,ee=Q.offset;if(Mt.isInstancedInterleavedBuffer||Mt.isInstancedBufferAttribute){for(let kt=0;kt<K.locationSize;kt++)f(K.location+kt,Mt.meshPerAttribute);D.isInstancedMesh!==!0&&L._maxInstanceCount===void 0&&(L._maxInstanceCount=Mt.meshPerAttribute*Mt.count)}else for(let kt=0;kt<K.locationSize;kt++)p(K.location+kt);n.bindBuffer(n.ARRAY_BUFFER,j);for(let kt=0;kt<K.locationSize;kt++)A(K.location+kt,ut/K.locationSize,pt,nt,Gt*_t,(ee+ut/K.locationSize*kt)*_t,Tt)}else{if(Q.isInstancedBufferAttribute){for(let Mt=0;Mt<K.locationSize;Mt++)f(K.location+Mt,Q.meshPerAttribute);D.isInstancedMesh!==!0&&L._maxInstanceCount===void 0&&(L._maxInstanceCount=Q.meshPerAttribute*Q.count)}else for(let Mt=0;Mt<K.locationSize;Mt++)p(K.location+Mt);n.bindBuffer(n.ARRAY_BUFFER,j);for(let Mt=0;Mt<K.locationSize;Mt++)A(K.location+Mt,ut/K.locationSize,pt,nt,ut*_t,ut/K.locationSize*Mt*_t,Tt)}}else if(k!==void 0){const nt=k[lt];if(nt!==void 0)switch(nt.length){case 2:n.vertexAttrib2fv(K.location,nt);break;case 3:n.vertexAttrib3fv(K.location,nt);break;case 4:n.vertexAttrib4fv(K.location,nt);break;default:n.vertexAttrib1fv(K.location,nt)}}}}x()}function R(){z();for(const D in i){const I=i[D];for(const B in I){const L=I[B];for(const G in L){const Y=L[G];for(const k in Y)h(Y[k].object),delete Y[k];delete L[G]}}delete i[D]}}function E(D){if(i[D.id]===void 0)return;const I=i[D.id];for(const B in I){const L=I[B];for(const G in L){const Y=L[G];for(const k in Y)h(Y[k].object),delete Y[k];delete L[G]}}delete i[D.id]}function g(D){for(const I in i){const B=i[I];for(const L in B){const G=B[L];if(G[D.id]===void 0)continue;const Y=G[D.id];for(const k in Y)h(Y[k].object),delete Y[k];delete G[D.id]}}}function T(D){for(const I in i){const B=i[I],L=D.isInstancedMesh===!0?D.id:0,G=B[L];if(G!==void 0){for(const Y in G){const k=G[Y];for(const lt in k)h(k[lt].object),delete k[lt];delete G[Y]}delete B[L],Object.keys(B).length===0&&delete i[I]}}}function z(){U(),a=!0,r!==s&&(r=s,l(r.object))}function U(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:o,reset:z,resetDefaultState:U,dispose:R,releaseStatesOfGeometry:E,releaseStatesOfObject:T,releaseStatesOfProgram:g,initAttributes:M,enableAttribute:p,disableUnusedAttributes:x}}function dx(n,t,e){let i;function s(c){i=c}function r(c,l){n.drawArrays(i,c,l),e.update(l,i,1)}function a(c,l,h){h!==0&&(n.drawArraysInstanced(i,c,l,h),e.update(l,i,h))}function o(c,l,h){if(h===0)return;t.get("WEBGL_multi_draw").multiDrawArraysWEBGL(i,c,0,l,0,h);let u=0;for(let m=0;m<h;m++)u+=l[m];e.update(u,i,1)}this.setMode=s,this.render=r,this.renderInstances=a,this.renderMultiDraw=o}function fx(n,t,e,i){let s;function r(){if(s!==void 0)return s;if(t.has("EXT_texture_filter_anisotropic")===!0){const g=t.get("EXT_texture_filter_anisotropic");s=n.getParameter(g.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function a(g){return!(g!==Ei&&i.convert(g)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(g){const T=g===Hi&&(t.has("EXT_color_buffer_half_float")||t.has("EXT_color_buffer_float"));return!(g!==Jn&&g!==Bi&&!T&&i.convert(g)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_TYPE))}function c(g){if(g==="highp"){if(n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.HIGH_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.HIGH_FLOAT).precision>0)return"highp";g="mediump"}return g==="mediump"&&n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.MEDIUM_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let l=e.precision!==void 0?e.precision:"highp";const h=c(l);h!==l&&(Kt("WebGLRenderer:",l,"not supported, using",h,"instead."),l=h);const d=e.reversedDepthBuffer===!0&&t.has("EXT_clip_control"),u=e.logarithmicDepthBuffer===!0&&d===!1;e.reversedDepthBuffer===!0&&d===!1&&Kt("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),e.logarithmicDepthBuffer===!0&&d===!0&&Kt("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");const m=n.getParameter(n.MAX_TEXTURE_IMAGE_UNITS),v=n.getParameter(n.MAX_VERTEX_TEXTURE_IMAGE_UNITS),M=n.getParameter(n.MAX_TEXTURE_SIZE),p=n.getParameter(n.MAX_CUBE_MAP_TEXTURE_SIZE),f=n.getParameter(n.MAX_VERTEX_ATTRIBS),x=n.getParameter(n.MAX_VERTEX_UNIFORM_VECTORS),A=n.getParameter(n.MAX_VARYING_VECTORS),y=n.getParameter(n.MAX_FRAGMENT_UNIFORM_VECTORS),R=n.getParameter(n.MAX_SAMPLES),E=n.getParameter(n.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:c,textureFormatReadable:a,textureTypeReadable:o,precision:l,logarithmicDepthBuffer:u,reversedDepthBuffer:d,maxTextures:m,maxVertexTextures:v,maxTextureSize:M,maxCubemapSize:p,maxAttributes:f,maxVertexUniforms:x,maxVaryings:A,maxFragmentUniforms:y,maxSamples:R,samples:E}}function px(n){const t=this;let e=null,i=0,s=!1,r=!1;const a=new Si,o=new te,c={value:null,needsUpdate:!1};this.uniform=c,this.numPlanes=0,this.numIntersection=0,this.init=function(d,u){const m=d.length!==0||u||i!==0||s;return s=u,i=d.length,m},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(d,u){e=h(d,u,0)},this.setState=function(d,u,m){const v=d.clippingPlanes,M=d.clipIntersection,p=d.clipShadows,f=n.get(d);if(!s||v===null||v.length===0||r&&!p)r?h(null):l();else{const x=r?0:i,A=x*4;let y=f.clippingState||null;c.value=y,y=h(v,u,A,m);for(let R=0;R!==A;++R)y[R]=e[R];f.clippingState=y,this.numIntersection=M?this.numPlanes:0,this.numPlanes+=x}};function l(){c.value!==e&&(c.value=e,c.needsUpdate=i>0),t.numPlanes=i,t.numIntersection=0}function h(d,u,m,v){const M=d!==null?d.length:0;let p=null;if(M!==0){if(p=c.value,v!==!0||p===null){const f=m+M*4,x=u.matrixWorldInverse;o.getNormalMatrix(x),(p===null||p.length<f)&&(p=new Float32Array(f));for(let A=0,y=m;A!==M;++A,y+=4)a.copy(d[A]).applyMatrix4(x,o),a.normal.toArray(p,y),p[y+3]=a.constant}c.value=p,c.needsUpdate=!0}return t.numPlanes=M,t.numIntersection=0,p}}class Ah extends hi{constructor(t=1,e={}){super(t,t,e),this.isWebGLCubeRenderTarget=!0;const i={width:t,height:t,depth:1},s=[i,i,i,i,i,i];this.texture=new Qf(s),this._setTextureOptions(e),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(t,e){this.texture.type=e.type,this.texture.colorSpace=e.colorSpace,this.texture.generateMipmaps=e.generateMipmaps,this.texture.minFilter=e.minFilter,this.texture.magFilter=e.magFilter;const i={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},s=new Aa(5,5,5),r=new As({name:"CubemapFromEquirect",uniforms:Cr(i.uniforms),vertexShader:i.vertexShader,fragmentShader:i.fragmentShader,side:Vn,blending:Er});r.uniforms.tEquirect.value=e;const a=new bn(s,r),o=e.minFilter;return e.minFilter===Ss&&(e.minFilter=zn),new qc(1,10,this).update(t,a),e.minFilter=o,a.geometry.dispose(),a.material.dispose(),this}clear(t,e=!0,i=!0,s=!0){const r=t.getRenderTarget();for(let a=0;a<6;a++)t.setRenderTarget(this,a),t.clear(e,i,s);t.setRenderTarget(r)}}const Ku=256,mx=3,gx=20,lp=256,cp=16,_x=3,vx=new V,xx=new le;class No{constructor(t){this._renderer=t,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new qc(1,10,null),this._boxMesh=new bn(new Aa(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(t,e=0,i=.1,s=100,r={}){const{size:a=256,position:o=vx}=r,c=this._renderer;this._setSize(a);const l=this._allocateTarget(),h=this._getSourceTarget(!0);e>0&&(h.texture.mipmapsAutoUpdate=!1);const d=c.autoClear,u=c.autoClearColor,m=c.autoClearDepth,v=c.autoClearStencil,M=t.background;c.autoClear=!0,c.autoClearColor=!0,c.autoClearDepth=!0,c.autoClearStencil=!0,M===null&&(t.background=c.getClearColor(xx));const p=new qc(i,s,h);return p.position.copy(o),p.update(c,t),c.autoClear=d,c.autoClearColor=u,c.autoClearDepth=m,c.autoClearStencil=v,t.background=M,e>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(l,e)),this._applyPMREM(l),l}fromEquirectangular(t,e=null){return this._fromTexture(t,e)}fromCubemap(t,e=null){return this._fromTexture(t,e)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=Qu(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Ju(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(t,e){return e>0?1-Math.sqrt(1-t/e):0}_setSize(t){this._cubeSize=Math.max(Ku,zg(t))}_fromTexture(t,e){t.mapping===Tr||t.mapping===_a?this._setSize(t.image.length===0?Ku:t.image[0].width||t.image[0].image.width):this._setSize(t.image.width/4);const i=e||this._allocateTarget();return this._textureToCubemap(t),this._applyPMREM(i),i}_allocateTarget(){const t=this._cubeSize,e=Zu(t,!1,!1),i=Math.log2(t)-mx;for(let s=0;s<=i;s++)e.texture.mipmaps.push({width:t>>s,height:t>>s});return e.texture.name="PMREM",e.texture.isPMREMTexture=!0,e}_getSourceTarget(t=!1){const e=this._cubeSize,i=this._sourceTarget;return(i===null||i.width!==e||t&&i.depthBuffer===!1)&&(i!==null&&i.dispose(),this._sourceTarget=Zu(e,!0,t)),this._sourceTarget}_compileMaterial(t){this._boxMesh.material=t,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(t,e,i){const s=this._boxMesh,r=this._cubeCamera;s.material=i,r.renderTarget=t,r.activeMipmapLevel=e;const a=t.width>>e;t.viewport.set(0,0,a,a),r.update(this._renderer,s),t.viewport.set(0,0,t.width,t.height)}_textureToCubemap(t){let e;t.mapping===Tr||t.mapping===_a?(this._cubemapMaterial===null&&(this._cubemapMaterial=Qu()),e=this._cubemapMaterial,e.uniforms.flipEnvMap.value=t.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Ju()),e=this._equirectMaterial),e.uniforms.envMap.value=t,this._renderCube(this._getSourceTarget(),0,e)}_applyPMREM(t){this._ggxMaterial===null&&(this._ggxMaterial=Sx(),this._integrationMaterial=Mx());const e=this._cubeSize,i=t.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;const r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(e/cp);for(let a=0;a<=i;a++){const o=No.lodToRoughness(a,i);if(a>i-_x)r.roughness.value=o,this._renderCube(t,a,this._integrationMaterial);else{const c=o>0?Math.log2(e)+.5*Math.log2(6/(lp*Math.pow(o,4)))+.5:0;s.roughness.value=o,s.lodBias.value=c,this._renderCube(t,a,this._ggxMaterial)}}}_blur(t,e){this._blurMaterial===null&&(this._blurMaterial=yx());const i=this._blurMaterial,s=i.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(e,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(t,0,i),s.envMap.value=t.texture,this._renderCube(r,0,i)}}function Zu(n,t,e){return new Ah(n,{minFilter:Ss,generateMipmaps:t,type:Hi,colorSpace:Ao,depthBuffer:e})}function Ra(n,t,e){return new As({name:n,uniforms:t,vertexShader:ae.cube_vert,fragmentShader:e,side:Vn,blending:Er,depthTest:!1,depthWrite:!1})}function Sx(){return Ra("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${lp}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function Mx(){return Ra("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:cp}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function yx(){return Ra("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${gx}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function Ju(){return Ra("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function Qu(){return Ra("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function Ex(n){let t=new WeakMap,e=new WeakMap,i=null;function s(u,m=!1){return u==null?null:m?a(u):r(u)}function r(u){if(u&&u.isTexture){const m=u.mapping;if(m===ll||m===cl)if(t.has(u)){const v=t.get(u).texture;return o(v,u.mapping)}else{const v=u.image;if(v&&v.height>0){const M=new Ah(v.height);return M.fromEquirectangularTexture(n,u),t.set(u,M),u.addEventListener("dispose",l),o(M.texture,u.mapping)}else return null}}return u}function a(u){if(u&&u.isTexture&&u.isPMREMTexture!==!0){const m=u.mapping,v=m===ll||m===cl,M=m===Tr||m===_a;if(v||M){let p=e.get(u);const f=p!==void 0?p.texture.pmremVersion:0;if(u.isRenderTargetTexture&&u.pmremVersion!==f)return i===null&&(i=new No(n)),p=v?i.fromEquirectangular(u,p):i.fromCubemap(u,p),p.texture.pmremVersion=u.pmremVersion,e.set(u,p),p.texture;if(p!==void 0)return p.texture;{const x=u.image;return v&&x&&x.height>0||M&&x&&c(x)?(i===null&&(i=new No(n)),p=v?i.fromEquirectangular(u):i.fromCubemap(u),p.texture.pmremVersion=u.pmremVersion,e.set(u,p),u.addEventListener("dispose",h),p.texture):null}}}return u}function o(u,m){return m===ll?u.mapping=Tr:m===cl&&(u.mapping=_a),u}function c(u){let m=0;const v=6;for(let M=0;M<v;M++)u[M]!==void 0&&m++;return m===v}function l(u){const m=u.target;m.removeEventListener("dispose",l);const v=t.get(m);v!==void 0&&(t.delete(m),v.dispose())}function h(u){const m=u.target;m.removeEventListener("dispose",h);const v=e.get(m);v!==void 0&&(e.delete(m),v.dispose())}function d(){t=new WeakMap,e=new WeakMap,i!==null&&(i.dispose(),i=null)}return{get:s,dispose:d}}function bx(n){const t={};function e(i){if(t[i]!==void 0)return t[i];const s=n.getExtension(i);return t[i]=s,s}return{has:function(i){return e(i)!==null},init:function(){e("EXT_color_buffer_float"),e("WEBGL_clip_cull_distance"),e("OES_texture_float_linear"),e("EXT_color_buffer_half_float"),e("WEBGL_multisampled_render_to_texture"),e("WEBGL_render_shared_exponent")},get:function(i){const s=e(i);return s===null&&yo("WebGLRenderer: "+i+" extension not supported."),s}}}function wx(n,t,e,i){const s={},r=new WeakMap,a=new FinalizationRegistry(v=>delete s[v]);function o(v){c(v.target)}function c(v){v.index!==null&&t.remove(v.index);for(const p in v.attributes)t.remove(v.attributes[p]);v.removeEventListener("dispose",o),delete s[v.id],a.unregister(v);const M=r.get(v);M&&(t.remove(M),r.delete(v)),i.releaseStatesOfGeometry(v),v.isInstancedBufferGeometry===!0&&delete v._maxInstanceCount,e.memory.geometries--}function l(v,M){return s[M.id]!==void 0||(M.addEventListener("dispose",o),s[M.id]=new WeakRef(M),a.register(M,M.id,M),e.memory.geometries++),M}function h(v){const M=v.attributes;for(const p in M)t.update(M[p],n.ARRAY_BUFFER)}function d(v){const M=v.index,p=v.attributes.position;let f=0;if(p===void 0)return;const x=M!==null?M.array.length:p.array.length/3-1,A=p.count>=65535?Jf:Zf,y=new A(Math.ceil(x/3)*6,1),R=y.array;if(M!==null){const g=M.array;f=M.version;for(let T=0,z=0;T<x;T+=3){const U=g[T+0],D=g[T+1],I=g[T+2];R[z++]=U,R[z++]=D,R[z++]=D,R[z++]=I,R[z++]=I,R[z++]=U}}else{f=p.version;for(let g=0,T=0;g<x;g+=3){const z=g+0,U=g+1,D=g+2;R[T++]=z,R[T++]=U,R[T++]=U,R[T++]=D,R[T++]=D,R[T++]=z}}y.version=f;const E=r.get(v);E&&t.remove(E),r.set(v,y)}function u(v){const M=r.get(v);if(M){const p=v.index;p!==null&&M.version<p.version&&d(v)}else d(v);return r.get(v)}function m(){for(const v in s){const M=s[v].deref();M!==void 0&&c(M)}}return{get:l,update:h,getWireframeAttribute:u,dispose:m}}function Tx(n,t,e){let i;function s(d){i=d}let r,a;function o(d){r=d.type,a=d.bytesPerElement}function c(d,u){n.drawElements(i,u,r,d*a),e.update(u,i,1)}function l(d,u,m){m!==0&&(n.drawElementsInstanced(i,u,r,d*a,m),e.update(u,i,m))}function h(d,u,m){if(m===0)return;t.get("WEBGL_multi_draw").multiDrawElementsWEBGL(i,u,0,r,d,0,m);let M=0;for(let p=0;p<m;p++)M+=u[p];e.update(M,i,1)}this.setMode=s,this.setIndex=o,this.render=c,this.renderInstances=l,this.renderMultiDraw=h}function Ax(n){const t={geometries:0,textures:0},e={frame:0,calls:0,triangles:0,points:0,lines:0};function i(r,a,o){switch(e.calls++,a){case n.TRIANGLES:e.triangles+=o*(r/3);break;case n.LINES:e.lines+=o*(r/2);break;case n.LINE_STRIP:e.lines+=o*(r-1);break;case n.LINE_LOOP:e.lines+=o*r;break;case n.POINTS:e.points+=o*r;break;default:ve("WebGLInfo: Unknown draw mode:",a);break}}function s(){e.calls=0,e.triangles=0,e.points=0,e.lines=0}return{memory:t,render:e,programs:null,autoReset:!0,reset:s,update:i}}function Rx(n,t,e){const i=new WeakMap,s=new Qe;function r(a,o,c){const l=a.morphTargetInfluences,h=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,d=h!==void 0?h.length:0;let u=i.get(o);if(u===void 0||u.count!==d){let U=function(){T.dispose(),i.delete(o),o.removeEventListener("dispose",U)};var m=U;u!==void 0&&u.texture.dispose();const v=o.morphAttributes.position!==void 0,M=o.morphAttributes.normal!==void 0,p=o.morphAttributes.color!==void 0,f=o.morphAttributes.position||[],x=o.morphAttributes.normal||[],A=o.morphAttributes.color||[];let y=0;v===!0&&(y=1),M===!0&&(y=2),p===!0&&(y=3);let R=o.attributes.position.count*y,E=1;R>t.maxTextureSize&&(E=Math.ceil(R/t.maxTextureSize),R=t.maxTextureSize);const g=new Float32Array(R*E*4*d),T=new Yf(g,R,E,d);T.type=Bi,T.needsUpdate=!0;const z=y*4;for(let D=0;D<d;D++){const I=f[D],B=x[D],L=A[D],G=R*E*4*D;for(let Y=0;Y<I.count;Y++){const k=Y*z;v===!0&&(s.fromBufferAttribute(I,Y),g[G+k+0]=s.x,g[G+k+1]=s.y,g[G+k+2]=s.z,g[G+k+3]=0),M===!0&&(s.fromBufferAttribute(B,Y),g[G+k+4]=s.x,g[G+k+5]=s.y,g[G+k+6]=s.z,g[G+k+7]=0),p===!0&&(s.fromBufferAttribute(L,Y),g[G+k+8]=s.x,g[G+k+9]=s.y,g[G+k+10]=s.z,g[G+k+11]=L.itemSize===4?s.w:1)}}u={count:d,texture:T,size:new Jt(R,E)},i.set(o,u),o.addEventListener("dispose",U)}if(a.isInstancedMesh===!0&&a.morphTexture!==null)c.getUniforms().setValue(n,"morphTexture",a.morphTexture,e);else{let v=0;for(let p=0;p<l.length;p++)v+=l[p];const M=o.morphTargetsRelative?1:1-v;c.getUniforms().setValue(n,"morphTargetBaseInfluence",M),c.getUniforms().setValue(n,"morphTargetInfluences",l)}c.getUniforms().setValue(n,"morphTargetsTexture",u.texture,e),c.getUniforms().setValue(n,"morphTargetsTextureSize",u.size)}return{update:r}}function Cx(n,t,e,i,s){let r=new WeakMap;function a(l){const h=s.render.frame,d=l.geometry,u=t.get(l,d);if(r.get(u)!==h&&(t.update(u),r.set(u,h)),l.isInstancedMesh&&(l.hasEventListener("dispose",c)===!1&&l.addEventListener("dispose",c),r.get(l)!==h&&(e.update(l.instanceMatrix,n.ARRAY_BUFFER),l.instanceColor!==null&&e.update(l.instanceColor,n.ARRAY_BUFFER),r.set(l,h))),l.isSkinnedMesh){const m=l.skeleton;r.get(m)!==h&&(m.update(),r.set(m,h))}return u}function o(){r=new WeakMap}function c(l){const h=l.target;h.removeEventListener("dispose",c),i.releaseStatesOfObject(h),e.remove(h.instanceMatrix),h.instanceColor!==null&&e.remove(h.instanceColor)}return{update:a,dispose:o}}const Px={[Rf]:"LINEAR_TONE_MAPPING",[Cf]:"REINHARD_TONE_MAPPING",[Pf]:"CINEON_TONE_MAPPING",[Lf]:"ACES_FILMIC_TONE_MAPPING",[Nf]:"AGX_TONE_MAPPING",[If]:"NEUTRAL_TONE_MAPPING",[Df]:"CUSTOM_TONE_MAPPING"};function Lx(n,t,e,i,s,r){const a=new hi(t,e,{type:n,depthBuffer:s,stencilBuffer:r,samples:i?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1});let o=null,c=null,l=null;const h=new ln;h.setAttribute("position",new We([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new We([0,2,0,0,2,0],2));const d=new g_({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),u=new bn(h,d),m=new Th(-1,1,1,-1,0,1);let v=null,M=null,p=!1,f,x=null,A=[],y=!1;this.setSize=function(R,E){a.setSize(R,E),o!==null&&o.setSize(R,E),c!==null&&c.setSize(R,E);for(let g=0;g<A.length;g++){const T=A[g];T.setSize&&T.setSize(R,E)}},this.setEffects=function(R){A=R,y=A.length>0&&A[0].isRenderPass===!0;const E=a.width,g=a.height;A.length>0&&o===null&&(o=new hi(E,g,{type:Hi,depthBuffer:!1,stencilBuffer:!1}),c=new hi(E,g,{type:Hi,depthBuffer:!1,stencilBuffer:!1}));const T=s===!0&&A.some(z=>z.needsDepthTexture===!0);T!==(a.depthTexture!==null)&&(T===!0&&l===null&&(l=new Rr(E,g),r===!0&&(l.format=Ms,l.type=Ar)),a.dispose(),a.depthTexture=T?l:null,a.resolveDepthBuffer=T,a.storeMultisampledDepthBuffer=T);for(let z=0;z<A.length;z++){const U=A[z];U.setSize&&U.setSize(E,g),T&&U.needsDepthTexture===!0&&U.setDepthTexture&&U.setDepthTexture(l)}},this.begin=function(R,E){if(p||R.toneMapping===ts&&A.length===0)return!1;if(x=E,E!==null){const g=E.width,T=E.height;(a.width!==g||a.height!==T)&&this.setSize(g,T)}return y===!1&&R.setRenderTarget(a),f=R.toneMapping,R.toneMapping=ts,!0},this.hasRenderPass=function(){return y},this.end=function(R,E){R.toneMapping=f,p=!0;let g=a,T=o;for(let z=0;z<A.length;z++){const U=A[z];U.enabled!==!1&&(U.render(R,T,g,E),U.needsSwap!==!1&&(g=T,T=T===o?c:o))}if(v!==R.outputColorSpace||M!==R.toneMapping){v=R.outputColorSpace,M=R.toneMapping,d.defines={},me.getTransfer(v)===Ae&&(d.defines.SRGB_TRANSFER="");const z=Px[M];z&&(d.defines[z]=""),d.needsUpdate=!0}d.uniforms.tDiffuse.value=g.texture,R.setRenderTarget(x),R.render(u,m),x=null,p=!1},this.isCompositing=function(){return p},this.dispose=function(){a.dispose(),o!==null&&o.dispose(),c!==null&&c.dispose(),h.dispose(),d.dispose()}}const hp=new Hn,up=new Rr(1,1),dp=new jf(1),fp=new Yf,pp=new Yg,mp=new Qf,ju=[],td=[],ed=new Float32Array(16),nd=new Float32Array(9),id=new Float32Array(4);function Ur(n,t,e){const i=n[0];if(i<=0||i>0)return n;const s=t*e;let r=ju[s];if(r===void 0&&(r=new Float32Array(s),ju[s]=r),t!==0){i.toArray(r,0);for(let a=1,o=0;a!==t;++a)o+=e,n[a].toArray(r,o)}return r}function pn(n,t){if(n.length!==t.length)return!1;for(let e=0,i=n.length;e<i;e++)if(n[e]!==t[e])return!1;return!0}function mn(n,t){for(let e=0,i=t.length;e<i;e++)n[e]=t[e]}function ko(n,t){let e=td[t];e===void 0&&(e=new Int32Array(t),td[t]=e);for(let i=0;i!==t;++i)e[i]=n.allocateTextureUnit();return e}function Dx(n,t){const e=this.cache;e[0]!==t&&(n.uniform1f(this.addr,t),e[0]=t)}function Nx(n,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(n.uniform2f(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(pn(e,t))return;n.uniform2fv(this.addr,t),mn(e,t)}}function Ix(n,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(n.uniform3f(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else if(t.r!==void 0)(e[0]!==t.r||e[1]!==t.g||e[2]!==t.b)&&(n.uniform3f(this.addr,t.r,t.g,t.b),e[0]=t.r,e[1]=t.g,e[2]=t.b);else{if(pn(e,t))return;n.uniform3fv(this.addr,t),mn(e,t)}}function Ux(n,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(n.uniform4f(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(pn(e,t))return;n.uniform4fv(this.addr,t),mn(e,t)}}function Fx(n,t){const e=this.cache,i=t.elements;if(i===void 0){if(pn(e,t))return;n.uniformMatrix2fv(this.addr,!1,t),mn(e,t)}else{if(pn(e,i))return;id.set(i),n.uniformMatrix2fv(this.addr,!1,id),mn(e,i)}}function Ox(n,t){const e=this.cache,i=t.elements;if(i===void 0){if(pn(e,t))return;n.uniformMatrix3fv(this.addr,!1,t),mn(e,t)}else{if(pn(e,i))return;nd.set(i),n.uniformMatrix3fv(this.addr,!1,nd),mn(e,i)}}function Bx(n,t){const e=this.cache,i=t.elements;if(i===void 0){if(pn(e,t))return;n.uniformMatrix4fv(this.addr,!1,t),mn(e,t)}else{if(pn(e,i))return;ed.set(i),n.uniformMatrix4fv(this.addr,!1,ed),mn(e,i)}}function zx(n,t){const e=this.cache;e[0]!==t&&(n.uniform1i(this.addr,t),e[0]=t)}function kx(n,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(n.uniform2i(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(pn(e,t))return;n.uniform2iv(this.addr,t),mn(e,t)}}function Hx(n,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(n.uniform3i(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(pn(e,t))return;n.uniform3iv(this.addr,t),mn(e,t)}}function Gx(n,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(n.uniform4i(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(pn(e,t))return;n.uniform4iv(this.addr,t),mn(e,t)}}function Vx(n,t){const e=this.cache;e[0]!==t&&(n.uniform1ui(this.addr,t),e[0]=t)}function Wx(n,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(n.uniform2ui(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(pn(e,t))return;n.uniform2uiv(this.addr,t),mn(e,t)}}function Xx(n,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(n.uniform3ui(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(pn(e,t))return;n.uniform3uiv(this.addr,t),mn(e,t)}}function $x(n,t){const e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(n.uniform4ui(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(pn(e,t))return;n.uniform4uiv(this.addr,t),mn(e,t)}}function Ho(n){return n.version===0&&(n.compareFunction=Xf,n.needsUpdate=!0),n}function Yx(n,t,e){const i=this.cache,s=e.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_2D_SHADOW?r=Ho(up):r=hp,e.setTexture2D(t||r,s)}function qx(n,t,e){const i=this.cache,s=e.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),e.setTexture3D(t||pp,s)}function Kx(n,t,e){const i=this.cache,s=e.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_CUBE_SHADOW?r=Ho(dp):r=mp,e.setTextureCube(t||r,s)}function Zx(n,t,e){const i=this.cache,s=e.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),e.setTexture2DArray(t||fp,s)}function Jx(n){switch(n){case 5126:return Dx;case 35664:return Nx;case 35665:return Ix;case 35666:return Ux;case 35674:return Fx;case 35675:return Ox;case 35676:return Bx;case 5124:case 35670:return zx;case 35667:case 35671:return kx;case 35668:case 35672:return Hx;case 35669:case 35673:return Gx;case 5125:return Vx;case 36294:return Wx;case 36295:return Xx;case 36296:return $x;case 35678:case 36198:case 36298:case 36306:case 35682:return Yx;case 35679:case 36299:case 36307:return qx;case 35680:case 36300:case 36308:case 36293:return Kx;case 36289:case 36303:case 36311:case 36292:return Zx}}function Qx(n,t){n.uniform1fv(this.addr,t)}function jx(n,t){const e=Ur(t,this.size,2);n.uniform2fv(this.addr,e)}function tS(n,t){const e=Ur(t,this.size,3);n.uniform3fv(this.addr,e)}function eS(n,t){const e=Ur(t,this.size,4);n.uniform4fv(this.addr,e)}function nS(n,t){const e=Ur(t,this.size,4);n.uniformMatrix2fv(this.addr,!1,e)}function iS(n,t){const e=Ur(t,this.size,9);n.uniformMatrix3fv(this.addr,!1,e)}function sS(n,t){const e=Ur(t,this.size,16);n.uniformMatrix4fv(this.addr,!1,e)}function rS(n,t){n.uniform1iv(this.addr,t)}function aS(n,t){n.uniform2iv(this.addr,t)}function oS(n,t){n.uniform3iv(this.addr,t)}function lS(n,t){n.uniform4iv(this.addr,t)}function cS(n,t){n.uniform1uiv(this.addr,t)}function hS(n,t){n.uniform2uiv(this.addr,t)}function uS(n,t){n.uniform3uiv(this.addr,t)}function dS(n,t){n.uniform4uiv(this.addr,t)}function fS(n,t,e){const i=this.cache,s=t.length,r=ko(e,s);pn(i,r)||(n.uniform1iv(this.addr,r),mn(i,r));let a;this.type===n.SAMPLER_2D_SHADOW?a=Ho(up):a=hp;for(let o=0;o!==s;++o)e.setTexture2D(t[o]||a,r[o])}function pS(n,t,e){const i=this.cache,s=t.length,r=ko(e,s);pn(i,r)||(n.uniform1iv(this.addr,r),mn(i,r));for(let a=0;a!==s;++a)e.setTexture3D(t[a]||pp,r[a])}function mS(n,t,e){const i=this.cache,s=t.length,r=ko(e,s);pn(i,r)||(n.uniform1iv(this.addr,r),mn(i,r));let a;this.type===n.SAMPLER_CUBE_SHADOW?a=Ho(dp):a=mp;for(let o=0;o!==s;++o)e.setTextureCube(t[o]||a,r[o])}function gS(n,t,e){const i=this.cache,s=t.length,r=ko(e,s);pn(i,r)||(n.uniform1iv(this.addr,r),mn(i,r));for(let a=0;a!==s;++a)e.setTexture2DArray(t[a]||fp,r[a])}function _S(n){switch(n){case 5126:return Qx;case 35664:return jx;case 35665:return tS;case 35666:return eS;case 35674:return nS;case 35675:return iS;case 35676:return sS;case 5124:case 35670:return rS;case 35667:case 35671:return aS;case 35668:case 35672:return oS;case 35669:case 35673:return lS;case 5125:return cS;case 36294:return hS;case 36295:return uS;case 36296:return dS;case 35678:case 36198:case 36298:case 36306:case 35682:return fS;case 35679:case 36299:case 36307:return pS;case 35680:case 36300:case 36308:case 36293:return mS;case 36289:case 36303:case 36311:case 36292:return gS}}class vS{constructor(t,e,i){this.id=t,this.addr=i,this.cache=[],this.type=e.type,this.setValue=Jx(e.type)}}class xS{constructor(t,e,i){this.id=t,this.addr=i,this.cache=[],this.type=e.type,this.size=e.size,this.setValue=_S(e.type)}}class SS{constructor(t){this.id=t,this.seq=[],this.map={}}setValue(t,e,i){const s=this.seq;for(let r=0,a=s.length;r!==a;++r){const o=s[r];o.setValue(t,e[o.id],i)}}}const Ol=/(\w+)(\])?(\[|\.)?/g;function sd(n,t){n.seq.push(t),n.map[t.id]=t}function MS(n,t,e){const i=n.name,s=i.length;for(Ol.lastIndex=0;;){const r=Ol.exec(i),a=Ol.lastIndex;let o=r[1];const c=r[2]==="]",l=r[3];if(c&&(o=o|0),l===void 0||l==="["&&a+2===s){sd(e,l===void 0?new vS(o,n,t):new xS(o,n,t));break}else{let d=e.map[o];d===void 0&&(d=new SS(o),sd(e,d)),e=d}}}class Eo{constructor(t,e){this.seq=[],this.map={};const i=t.getProgramParameter(e,t.ACTIVE_UNIFORMS);for(let a=0;a<i;++a){const o=t.getActiveUniform(e,a),c=t.getUniformLocation(e,o.name);MS(o,c,this)}const s=[],r=[];for(const a of this.seq)a.type===t.SAMPLER_2D_SHADOW||a.type===t.SAMPLER_CUBE_SHADOW||a.type===t.SAMPLER_2D_ARRAY_SHADOW?s.push(a):r.push(a);s.length>0&&(this.seq=s.concat(r))}setValue(t,e,i,s){const r=this.map[e];r!==void 0&&r.setValue(t,i,s)}setOptional(t,e,i){const s=e[i];s!==void 0&&this.setValue(t,i,s)}static upload(t,e,i,s){for(let r=0,a=e.length;r!==a;++r){const o=e[r],c=i[o.id];c.needsUpdate!==!1&&o.setValue(t,c.value,s)}}static seqWithValue(t,e){const i=[];for(let s=0,r=t.length;s!==r;++s){const a=t[s];a.id in e&&i.push(a)}return i}}function rd(n,t,e){const i=n.createShader(t);return n.shaderSource(i,e),n.compileShader(i),i}const yS=37297;let ES=0;function bS(n,t){const e=n.split(`
`),i=[],s=Math.max(t-6,0),r=Math.min(t+6,e.length);for(let a=s;a<r;a++){const o=a+1;i.push(`${o===t?">":" "} ${o}: ${e[a]}`)}return i.join(`
`)}const ad=new te;function wS(n){me._getMatrix(ad,me.workingColorSpace,n);const t=`mat3( ${ad.elements.map(e=>e.toFixed(4))} )`;switch(me.getTransfer(n)){case Ro:return[t,"LinearTransferOETF"];case Ae:return[t,"sRGBTransferOETF"];default:return Kt("WebGLProgram: Unsupported color space: ",n),[t,"LinearTransferOETF"]}}function od(n,t,e){const i=n.getShaderParameter(t,n.COMPILE_STATUS),r=(n.getShaderInfoLog(t)||"").trim();if(i&&r==="")return"";const a=/ERROR: 0:(\d+)/.exec(r);if(a){const o=parseInt(a[1]);return e.toUpperCase()+`

`+r+`

`+bS(n.getShaderSource(t),o)}else return r}function TS(n,t){const e=wS(t);return[`vec4 ${n}( vec4 value ) {`,`	return ${e[1]}( vec4( ${e[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}const AS={[Rf]:"Linear",[Cf]:"Reinhard",[Pf]:"Cineon",[Lf]:"ACESFilmic",[Nf]:"AgX",[If]:"Neutral",[Df]:"Custom"};function RS(n,t){const e=AS[t];return e===void 0?(Kt("WebGLProgram: Unsupported toneMapping:",t),"vec3 "+n+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+n+"( vec3 color ) { return "+e+"ToneMapping( color ); }"}const so=new V;function CS(){me.getLuminanceCoefficients(so);const n=so.x.toFixed(4),t=so.y.toFixed(4),e=so.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${n}, ${t}, ${e} );`,"	return dot( weights, rgb );","}"].join(`
`)}function PS(n){return[n.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",n.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(ra).join(`
`)}function LS(n){const t=[];for(const e in n){const i=n[e];i!==!1&&t.push("#define "+e+" "+i)}return t.join(`
`)}function DS(n,t){const e={},i=n.getProgramParameter(t,n.ACTIVE_ATTRIBUTES);for(let s=0;s<i;s++){const r=n.getActiveAttrib(t,s),a=r.name;let o=1;r.type===n.FLOAT_MAT2&&(o=2),r.type===n.FLOAT_MAT3&&(o=3),r.type===n.FLOAT_MAT4&&(o=4),e[a]={type:r.type,location:n.getAttribLocation(t,a),locationSize:o}}return e}function ra(n){return n!==""}function ld(n,t){const e=t.numSpotLightShadows+t.numSpotLightMaps-t.numSpotLightShadowsWithMaps;return n.replace(/NUM_SUN_LIGHTS/g,t.numSunLights).replace(/NUM_DIR_LIGHTS/g,t.numDirLights).replace(/NUM_SPOT_LIGHTS/g,t.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,t.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,e).replace(/NUM_RECT_AREA_LIGHTS/g,t.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,t.numPointLights).replace(/NUM_HEMI_LIGHTS/g,t.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,t.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,t.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,t.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,t.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,t.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,t.numLightProbeGrids)}function cd(n,t){return n.replace(/NUM_CLIPPING_PLANES/g,t.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,t.numClippingPlanes-t.numClipIntersection)}const NS=/^[ \t]*#include +<([\w\d./]+)>/gm;function Zc(n){return n.replace(NS,IS)}function IS(n,t){const e=ae[t];if(e===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+t+">");return Zc(e)}const US=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function hd(n){return n.replace(US,FS)}function FS(n,t,e,i){let s="";for(let r=parseInt(t);r<parseInt(e);r++)s+=i.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function ud(n){let t=`precision ${n.precision} float;
	precision ${n.precision} int;
	precision ${n.precision} sampler2D;
	precision ${n.precision} samplerCube;
	precision ${n.precision} sampler3D;
	precision ${n.precision} sampler2DArray;
	precision ${n.precision} sampler2DShadow;
	precision ${n.precision} samplerCubeShadow;
	precision ${n.precision} sampler2DArrayShadow;
	precision ${n.precision} isampler2D;
	precision ${n.precision} isampler3D;
	precision ${n.precision} isamplerCube;
	precision ${n.precision} isampler2DArray;
	precision ${n.precision} usampler2D;
	precision ${n.precision} usampler3D;
	precision ${n.precision} usamplerCube;
	precision ${n.precision} usampler2DArray;
	`;return n.precision==="highp"?t+=`
#define HIGH_PRECISION`:n.precision==="mediump"?t+=`
#define MEDIUM_PRECISION`:n.precision==="lowp"&&(t+=`
#define LOW_PRECISION`),t}const OS={[_o]:"SHADOWMAP_TYPE_PCF",[sa]:"SHADOWMAP_TYPE_VSM"};function BS(n){return OS[n.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}const zS={[_a]:"ENVMAP_MODE_REFRACTION"};function kS(n){return n.envMap===!1?"ENVMAP_MODE_REFLECTION":zS[n.envMapMode]||"ENVMAP_MODE_REFLECTION"}const HS={[Af]:"ENVMAP_BLENDING_MULTIPLY",[yg]:"ENVMAP_BLENDING_MIX",[Eg]:"ENVMAP_BLENDING_ADD"};function GS(n){return n.envMap===!1?"ENVMAP_BLENDING_NONE":HS[n.combine]||"ENVMAP_BLENDING_NONE"}function VS(n,t,e,i){const s=n.getContext(),r=e.defines;let a=e.vertexShader,o=e.fragmentShader;const c=BS(e),l=e.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=kS(e),d=GS(e),u=PS(e),m=LS(r),v=s.createProgram();let M,p,f=e.glslVersion?"#version "+e.glslVersion+`
`:"";e.isRawShaderMaterial?(M=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,m].filter(ra).join(`
`),M.length>0&&(M+=`
`),p=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,m].filter(ra).join(`
`),p.length>0&&(p+=`
`)):(M=[ud(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,m,e.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",e.batching?"#define USE_BATCHING":"",e.batchingColor?"#define USE_BATCHING_COLOR":"",e.instancing?"#define USE_INSTANCING":"",e.instancingColor?"#define USE_INSTANCING_COLOR":"",e.instancingMorph?"#define USE_INSTANCING_MORPH":"",e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.map?"#define USE_MAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+h:"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.displacementMap?"#define USE_DISPLACEMENTMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.mapUv?"#define MAP_UV "+e.mapUv:"",e.alphaMapUv?"#define ALPHAMAP_UV "+e.alphaMapUv:"",e.lightMapUv?"#define LIGHTMAP_UV "+e.lightMapUv:"",e.aoMapUv?"#define AOMAP_UV "+e.aoMapUv:"",e.emissiveMapUv?"#define EMISSIVEMAP_UV "+e.emissiveMapUv:"",e.bumpMapUv?"#define BUMPMAP_UV "+e.bumpMapUv:"",e.normalMapUv?"#define NORMALMAP_UV "+e.normalMapUv:"",e.displacementMapUv?"#define DISPLACEMENTMAP_UV "+e.displacementMapUv:"",e.metalnessMapUv?"#define METALNESSMAP_UV "+e.metalnessMapUv:"",e.roughnessMapUv?"#define ROUGHNESSMAP_UV "+e.roughnessMapUv:"",e.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+e.anisotropyMapUv:"",e.clearcoatMapUv?"#define CLEARCOATMAP_UV "+e.clearcoatMapUv:"",e.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+e.clearcoatNormalMapUv:"",e.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+e.clearcoatRoughnessMapUv:"",e.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+e.diffuseRoughnessMapUv:"",e.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+e.iridescenceMapUv:"",e.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+e.iridescenceThicknessMapUv:"",e.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+e.sheenColorMapUv:"",e.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+e.sheenRoughnessMapUv:"",e.specularMapUv?"#define SPECULARMAP_UV "+e.specularMapUv:"",e.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+e.specularColorMapUv:"",e.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+e.specularIntensityMapUv:"",e.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+e.transmissionMapUv:"",e.thicknessMapUv?"#define THICKNESSMAP_UV "+e.thicknessMapUv:"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexNormals?"#define HAS_NORMAL":"",e.vertexColors?"#define USE_COLOR":"",e.vertexAlphas?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.flatShading?"#define FLAT_SHADED":"",e.skinning?"#define USE_SKINNING":"",e.morphTargets?"#define USE_MORPHTARGETS":"",e.morphNormals&&e.flatShading===!1?"#define USE_MORPHNORMALS":"",e.morphColors?"#define USE_MORPHCOLORS":"",e.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+e.morphTextureStride:"",e.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+e.morphTargetsCount:"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+c:"",e.sizeAttenuation?"#define USE_SIZEATTENUATION":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(ra).join(`
`),p=[ud(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,m,e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",e.map?"#define USE_MAP":"",e.matcap?"#define USE_MATCAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+l:"",e.envMap?"#define "+h:"",e.envMap?"#define "+d:"",e.envMapPMREM?"#define ENVMAP_MAX_LOD "+e.envMapMaxLod+".0":"",e.envMapPMREM?"#define ENVMAP_SIZE "+e.envMapSize+".0":"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoat?"#define USE_CLEARCOAT":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.dispersion?"#define USE_DISPERSION":"",e.retroreflection?"#define USE_RETROREFLECTION":"",e.iridescence?"#define USE_IRIDESCENCE":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaTest?"#define USE_ALPHATEST":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.sheen?"#define USE_SHEEN":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexColors||e.instancingColor?"#define USE_COLOR":"",e.vertexAlphas||e.batchingColor?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.gradientMap?"#define USE_GRADIENTMAP":"",e.flatShading?"#define FLAT_SHADED":"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+c:"",e.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",e.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",e.toneMapping!==ts?"#define TONE_MAPPING":"",e.toneMapping!==ts?ae.tonemapping_pars_fragment:"",e.toneMapping!==ts?RS("toneMapping",e.toneMapping):"",e.dithering?"#define DITHERING":"",e.opaque?"#define OPAQUE":"",ae.colorspace_pars_fragment,TS("linearToOutputTexel",e.outputColorSpace),CS(),e.useDepthPacking?"#define DEPTH_PACKING "+e.depthPacking:"",`
`].filter(ra).join(`
`)),a=Zc(a),a=ld(a,e),a=cd(a,e),o=Zc(o),o=ld(o,e),o=cd(o,e),a=hd(a),o=hd(o),e.isRawShaderMaterial!==!0&&(f=`#version 300 es
`,M=[u,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+M,p=["#define varying in",e.glslVersion===mu?"":"layout(location = 0) out highp vec4 pc_fragColor;",e.glslVersion===mu?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+p);const x=f+M+a,A=f+p+o,y=rd(s,s.VERTEX_SHADER,x),R=rd(s,s.FRAGMENT_SHADER,A);s.attachShader(v,y),s.attachShader(v,R),e.index0AttributeName!==void 0?s.bindAttribLocation(v,0,e.index0AttributeName):e.hasPositionAttribute===!0&&s.bindAttribLocation(v,0,"position"),s.linkProgram(v);function E(U){if(n.debug.checkShaderErrors){const D=s.getProgramInfoLog(v)||"",I=s.getShaderInfoLog(y)||"",B=s.getShaderInfoLog(R)||"",L=D.trim(),G=I.trim(),Y=B.trim();let k=!0,lt=!0;if(s.getProgramParameter(v,s.LINK_STATUS)===!1)if(k=!1,typeof n.debug.onShaderError=="function")n.debug.onShaderError(s,v,y,R);else{const K=od(s,y,"vertex"),Q=od(s,R,"fragment");ve("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(v,s.VALIDATE_STATUS)+`

Material Name: `+U.name+`
Material Type: `+U.type+`

Program Info Log: `+L+`
`+K+`
`+Q)}else L!==""?Kt("WebGLProgram: Program Info Log:",L):(G===""||Y==="")&&(lt=!1);lt&&(U.diagnostics={runnable:k,programLog:L,vertexShader:{log:G,prefix:M},fragmentShader:{log:Y,prefix:p}})}s.deleteShader(y),s.deleteShader(R),g=new Eo(s,v),T=DS(s,v)}let g;this.getUniforms=function(){return g===void 0&&E(this),g};let T;this.getAttributes=function(){return T===void 0&&E(this),T};let z=e.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return z===!1&&(z=s.getProgramParameter(v,yS)),z},this.destroy=function(){i.releaseStatesOfProgram(this),s.deleteProgram(v),this.program=void 0},this.type=e.shaderType,this.name=e.shaderName,this.id=ES++,this.cacheKey=t,this.usedTimes=1,this.program=v,this.vertexShader=y,this.fragmentShader=R,this}let WS=0;class XS{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(t,e,i){const s=this._getShaderCacheForMaterial(t);return s.has(e)===!1&&(s.add(e),e.usedTimes++),s.has(i)===!1&&(s.add(i),i.usedTimes++),this}remove(t){const e=this.materialCache.get(t);for(const i of e)i.usedTimes--,i.usedTimes===0&&this.shaderCache.delete(i.code);return this.materialCache.delete(t),this}getVertexShaderStage(t){return this._getShaderStage(t.vertexShader)}getFragmentShaderStage(t){return this._getShaderStage(t.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(t){const e=this.materialCache;let i=e.get(t);return i===void 0&&(i=new Set,e.set(t,i)),i}_getShaderStage(t){const e=this.shaderCache;let i=e.get(t);return i===void 0&&(i=new $S(t),e.set(t,i)),i}}class $S{constructor(t){this.id=WS++,this.code=t,this.usedTimes=0}}function YS(n){return n===Ws||n===wo||n===To}function qS(n,t,e,i,s,r){const a=new Eh,o=new XS,c=new Set,l=[],h=new Map,d=i.logarithmicDepthBuffer,u={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function m(g){return c.add(g),g===0?"uv":`uv${g}`}function v(g,T,z,U,D,I){const B=U.fog,L=D.geometry,G=g.isMeshStandardMaterial||g.isMeshLambertMaterial||g.isMeshPhongMaterial?U.environment:null,Y=g.isMeshStandardMaterial||g.isMeshLambertMaterial&&!g.envMap||g.isMeshPhongMaterial&&!g.envMap,k=t.get(g.envMap||G,Y),lt=u[g.type];let K=i.precision;g.precision!==null&&(K=i.getMaxPrecision(g.precision),K!==g.precision&&Kt("WebGLProgram.getParameters:",g.precision,"not supported, using",K,"instead."));const Q=L.morphAttributes.position||L.morphAttributes.normal||L.morphAttributes.color,nt=Q!==void 0?Q.length:0;let ut=0;L.morphAttributes.position!==void 0&&(ut=1),L.morphAttributes.normal!==void 0&&(ut=2),L.morphAttributes.color!==void 0&&(ut=3);let ot,j,pt,_t;if(lt){const At=Oi[lt];ot=At.vertexShader,j=At.fragmentShader}else{ot=g.vertexShader,j=g.fragmentShader;const At=o.getVertexShaderStage(g),ie=o.getFragmentShaderStage(g);o.update(g,At,ie),pt=At.id,_t=ie.id}const Tt=n.getRenderTarget(),Mt=n.state.buffers.depth.getReversed(),Gt=D.isInstancedMesh===!0,ee=D.isBatchedMesh===!0,kt=!!g.map,oe=!!g.matcap,se=!!k,Qt=se&&k.isPMREMTexture===!0,He=!!g.aoMap,Ue=!!g.lightMap,je=!!g.bumpMap&&g.wireframe===!1,Re=!!g.normalMap,_n=!!g.displacementMap,ge=!!g.emissiveMap,cn=!!g.metalnessMap,Xe=!!g.roughnessMap,tn=g.anisotropy>0,O=g.clearcoat>0,Rt=g.diffuseRoughness>0,Xt=g.dispersion>0,ne=g.retroreflectivity>0,yt=g.iridescence>0,De=g.sheen>0,zt=g.transmission>0,Wt=tn&&!!g.anisotropyMap,C=O&&!!g.clearcoatMap,S=O&&!!g.clearcoatNormalMap,X=O&&!!g.clearcoatRoughnessMap,ht=Rt&&!!g.diffuseRoughnessMap,rt=yt&&!!g.iridescenceMap,gt=yt&&!!g.iridescenceThicknessMap,vt=De&&!!g.sheenColorMap,tt=De&&!!g.sheenRoughnessMap,it=!!g.specularMap,ft=!!g.specularColorMap,F=!!g.specularIntensityMap,st=zt&&!!g.transmissionMap,et=zt&&!!g.thicknessMap,Et=!!g.gradientMap,mt=!!g.alphaMap,St=g.alphaTest>0,Ht=!!g.alphaHash,Yt=!!g.extensions;let ct=ts;g.toneMapped&&(Tt===null||Tt.isXRRenderTarget===!0)&&(ct=n.toneMapping);const Ft=Qt?k.isCompressedCubeTexture?k.image[0].mipmaps:k.mipmaps:null,qt={shaderID:lt,shaderType:g.type,shaderName:g.name,vertexShader:ot,fragmentShader:j,defines:g.defines,customVertexShaderID:pt,customFragmentShaderID:_t,isRawShaderMaterial:g.isRawShaderMaterial===!0,glslVersion:g.glslVersion,precision:K,batching:ee,batchingColor:ee&&D._colorsTexture!==null,instancing:Gt,instancingColor:Gt&&D.instanceColor!==null,instancingMorph:Gt&&D.morphTexture!==null,outputColorSpace:Tt===null?n.outputColorSpace:Tt.isXRRenderTarget===!0?Tt.texture.colorSpace:me.workingColorSpace,alphaToCoverage:!!g.alphaToCoverage,map:kt,matcap:oe,envMap:se,envMapMode:se&&k.mapping,envMapPMREM:Qt,envMapMaxLod:Qt?Ft.length-1:null,envMapSize:Qt?Ft[0].width:null,aoMap:He,lightMap:Ue,bumpMap:je,normalMap:Re,displacementMap:_n,emissiveMap:ge,normalMapObjectSpace:Re&&g.normalMapType===Tg,normalMapTangentSpace:Re&&g.normalMapType===Yc,packedNormalMap:Re&&g.normalMapType===Yc&&YS(g.normalMap.format),metalnessMap:cn,roughnessMap:Xe,anisotropy:tn,anisotropyMap:Wt,clearcoat:O,clearcoatMap:C,clearcoatNormalMap:S,clearcoatRoughnessMap:X,diffuseRoughness:Rt,diffuseRoughnessMap:ht,dispersion:Xt,retroreflection:ne,iridescence:yt,iridescenceMap:rt,iridescenceThicknessMap:gt,sheen:De,sheenColorMap:vt,sheenRoughnessMap:tt,specularMap:it,specularColorMap:ft,specularIntensityMap:F,transmission:zt,transmissionMap:st,thicknessMap:et,gradientMap:Et,opaque:g.transparent===!1&&g.blending===ha&&g.alphaToCoverage===!1,alphaMap:mt,alphaTest:St,alphaHash:Ht,combine:g.combine,mapUv:kt&&m(g.map.channel),aoMapUv:He&&m(g.aoMap.channel),lightMapUv:Ue&&m(g.lightMap.channel),bumpMapUv:je&&m(g.bumpMap.channel),normalMapUv:Re&&m(g.normalMap.channel),displacementMapUv:_n&&m(g.displacementMap.channel),emissiveMapUv:ge&&m(g.emissiveMap.channel),metalnessMapUv:cn&&m(g.metalnessMap.channel),roughnessMapUv:Xe&&m(g.roughnessMap.channel),anisotropyMapUv:Wt&&m(g.anisotropyMap.channel),clearcoatMapUv:C&&m(g.clearcoatMap.channel),clearcoatNormalMapUv:S&&m(g.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:X&&m(g.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:ht&&m(g.diffuseRoughnessMap.channel),iridescenceMapUv:rt&&m(g.iridescenceMap.channel),iridescenceThicknessMapUv:gt&&m(g.iridescenceThicknessMap.channel),sheenColorMapUv:vt&&m(g.sheenColorMap.channel),sheenRoughnessMapUv:tt&&m(g.sheenRoughnessMap.channel),specularMapUv:it&&m(g.specularMap.channel),specularColorMapUv:ft&&m(g.specularColorMap.channel),specularIntensityMapUv:F&&m(g.specularIntensityMap.channel),transmissionMapUv:st&&m(g.transmissionMap.channel),thicknessMapUv:et&&m(g.thicknessMap.channel),alphaMapUv:mt&&m(g.alphaMap.channel),vertexTangents:!!L.attributes.tangent&&(Re||tn),vertexNormals:!!L.attributes.normal,vertexColors:g.vertexColors,vertexAlphas:g.vertexColors===!0&&!!L.attributes.color&&L.attributes.color.itemSize===4,pointsUvs:D.isPoints===!0&&!!L.attributes.uv&&(kt||mt),fog:!!B,useFog:g.fog===!0,fogExp2:!!B&&B.isFogExp2,flatShading:g.wireframe===!1&&(g.flatShading===!0||L.attributes.normal===void 0&&Re===!1&&(g.isMeshLambertMaterial||g.isMeshPhongMaterial||g.isMeshStandardMaterial||g.isMeshPhysicalMaterial)),sizeAttenuation:g.sizeAttenuation===!0,logarithmicDepthBuffer:d,reversedDepthBuffer:Mt,skinning:D.isSkinnedMesh===!0,hasPositionAttribute:L.attributes.position!==void 0,morphTargets:L.morphAttributes.position!==void 0,morphNormals:L.morphAttributes.normal!==void 0,morphColors:L.morphAttributes.color!==void 0,morphTargetsCount:nt,morphTextureStride:ut,numSunLights:T.sun.length,numDirLights:T.directional.length,numPointLights:T.point.length,numSpotLights:T.spot.length,numSpotLightMaps:T.spotLightMap.length,numRectAreaLights:T.rectArea.length,numHemiLights:T.hemi.length,numSunLightShadows:T.sunShadowMap.length,numDirLightShadows:T.directionalShadowMap.length,numPointLightShadows:T.pointShadowMap.length,numSpotLightShadows:T.spotShadowMap.length,numSpotLightShadowsWithMaps:T.numSpotLightShadowsWithMaps,numLightProbes:T.numLightProbes,numLightProbeGrids:I.filter(At=>At.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:g.dithering,shadowMapEnabled:n.shadowMap.enabled&&z.length>0,shadowMapType:n.shadowMap.type,toneMapping:ct,decodeVideoTexture:kt&&g.map.isVideoTexture===!0&&me.getTransfer(g.map.colorSpace)===Ae,decodeVideoTextureEmissive:ge&&g.emissiveMap.isVideoTexture===!0&&me.getTransfer(g.emissiveMap.colorSpace)===Ae,premultipliedAlpha:g.premultipliedAlpha,doubleSided:g.side===ci,flipSided:g.side===Vn,useDepthPacking:g.depthPacking>=0,depthPacking:g.depthPacking||0,index0AttributeName:g.index0AttributeName,extensionClipCullDistance:Yt&&g.extensions.clipCullDistance===!0&&e.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Yt&&g.extensions.multiDraw===!0||ee)&&e.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:e.has("KHR_parallel_shader_compile"),customProgramCacheKey:g.customProgramCacheKey()};return qt.vertexUv1s=c.has(1),qt.vertexUv2s=c.has(2),qt.vertexUv3s=c.has(3),c.clear(),qt}function M(g){const T=[];if(g.shaderID?T.push(g.shaderID):(T.push(g.customVertexShaderID),T.push(g.customFragmentShaderID)),g.defines!==void 0)for(const z in g.defines)T.push(z),T.push(g.defines[z]);return g.isRawShaderMaterial===!1&&(p(T,g),f(T,g),T.push(n.outputColorSpace)),T.push(g.customProgramCacheKey),T.join()}function p(g,T){g.push(T.precision),g.push(T.outputColorSpace),g.push(T.envMapMode),g.push(T.envMapPMREM),g.push(T.envMapMaxLod),g.push(T.envMapSize),g.push(T.mapUv),g.push(T.alphaMapUv),g.push(T.lightMapUv),g.push(T.aoMapUv),g.push(T.bumpMapUv),g.push(T.normalMapUv),g.push(T.displacementMapUv),g.push(T.emissiveMapUv),g.push(T.metalnessMapUv),g.push(T.roughnessMapUv),g.push(T.anisotropyMapUv),g.push(T.clearcoatMapUv),g.push(T.clearcoatNormalMapUv),g.push(T.clearcoatRoughnessMapUv),g.push(T.diffuseRoughnessMapUv),g.push(T.iridescenceMapUv),g.push(T.iridescenceThicknessMapUv),g.push(T.sheenColorMapUv),g.push(T.sheenRoughnessMapUv),g.push(T.specularMapUv),g.push(T.specularColorMapUv),g.push(T.specularIntensityMapUv),g.push(T.transmissionMapUv),g.push(T.thicknessMapUv),g.push(T.combine),g.push(T.fogExp2),g.push(T.sizeAttenuation),g.push(T.morphTargetsCount),g.push(T.numSunLights),g.push(T.numDirLights),g.push(T.numPointLights),g.push(T.numSpotLights),g.push(T.numSpotLightMaps),g.push(T.numHemiLights),g.push(T.numRectAreaLights),g.push(T.numSunLightShadows),g.push(T.numDirLightShadows),g.push(T.numPointLightShadows),g.push(T.numSpotLightShadows),g.push(T.numSpotLightShadowsWithMaps),g.push(T.numLightProbes),g.push(T.numLightProbeGrids),g.push(T.shadowMapType),g.push(T.toneMapping),g.push(T.numClippingPlanes),g.push(T.numClipIntersection),g.push(T.depthPacking)}function f(g,T){a.disableAll(),T.instancing&&a.enable(0),T.instancingColor&&a.enable(1),T.instancingMorph&&a.enable(2),T.matcap&&a.enable(3),T.envMap&&a.enable(4),T.normalMapObjectSpace&&a.enable(5),T.normalMapTangentSpace&&a.enable(6),T.clearcoat&&a.enable(7),T.iridescence&&a.enable(8),T.alphaTest&&a.enable(9),T.vertexColors&&a.enable(10),T.vertexAlphas&&a.enable(11),T.vertexUv1s&&a.enable(12),T.vertexUv2s&&a.enable(13),T.vertexUv3s&&a.enable(14),T.vertexTangents&&a.enable(15),T.anisotropy&&a.enable(16),T.alphaHash&&a.enable(17),T.batching&&a.enable(18),T.dispersion&&a.enable(19),T.retroreflection&&a.enable(24),T.diffuseRoughness&&a.enable(25),T.batchingColor&&a.enable(20),T.gradientMap&&a.enable(21),T.packedNormalMap&&a.enable(22),T.vertexNormals&&a.enable(23),g.push(a.mask),a.disableAll(),T.fog&&a.enable(0),T.useFog&&a.enable(1),T.flatShading&&a.enable(2),T.logarithmicDepthBuffer&&a.enable(3),T.reversedDepthBuffer&&a.enable(4),T.skinning&&a.enable(5),T.morphTargets&&a.enable(6),T.morphNormals&&a.enable(7),T.morphColors&&a.enable(8),T.premultipliedAlpha&&a.enable(9),T.shadowMapEnabled&&a.enable(10),T.doubleSided&&a.enable(11),T.flipSided&&a.enable(12),T.useDepthPacking&&a.enable(13),T.dithering&&a.enable(14),T.transmission&&a.enable(15),T.sheen&&a.enable(16),T.opaque&&a.enable(17),T.pointsUvs&&a.enable(18),T.decodeVideoTexture&&a.enable(19),T.decodeVideoTextureEmissive&&a.enable(20),T.alphaToCoverage&&a.enable(21),T.numLightProbeGrids>0&&a.enable(22),T.hasPositionAttribute&&a.enable(23),g.push(a.mask)}function x(g){const T=u[g.type];let z;if(T){const U=Oi[T];z=f_.clone(U.uniforms)}else z=g.uniforms;return z}function A(g,T){let z=h.get(T);return z!==void 0?++z.usedTimes:(z=new VS(n,T,g,s),l.push(z),h.set(T,z)),z}function y(g){if(--g.usedTimes===0){const T=l.indexOf(g);l[T]=l[l.length-1],l.pop(),h.delete(g.cacheKey),g.destroy()}}function R(g){o.remove(g)}function E(){o.dispose()}return{getParameters:v,getProgramCacheKey:M,getUniforms:x,acquireProgram:A,releaseProgram:y,releaseShaderCache:R,programs:l,dispose:E}}function KS(){let n=new WeakMap;function t(a){return n.has(a)}function e(a){let o=n.get(a);return o===void 0&&(o={},n.set(a,o)),o}function i(a){n.delete(a)}function s(a,o,c){n.get(a)[o]=c}function r(){n=new WeakMap}return{has:t,get:e,remove:i,update:s,dispose:r}}function ZS(n,t){return n.groupOrder!==t.groupOrder?n.groupOrder-t.groupOrder:n.renderOrder!==t.renderOrder?n.renderOrder-t.renderOrder:n.material.id!==t.material.id?n.material.id-t.material.id:n.materialVariant!==t.materialVariant?n.materialVariant-t.materialVariant:n.z!==t.z?n.z-t.z:n.id-t.id}function dd(n,t){return n.groupOrder!==t.groupOrder?n.groupOrder-t.groupOrder:n.renderOrder!==t.renderOrder?n.renderOrder-t.renderOrder:n.z!==t.z?t.z-n.z:n.id-t.id}function fd(){const n=[];let t=0;const e=[],i=[],s=[];function r(){t=0,e.length=0,i.length=0,s.length=0}function a(u){let m=0;return u.isInstancedMesh&&(m+=2),u.isSkinnedMesh&&(m+=1),m}function o(u,m,v,M,p,f){let x=n[t];return x===void 0?(x={id:u.id,object:u,geometry:m,material:v,materialVariant:a(u),groupOrder:M,renderOrder:u.renderOrder,z:p,group:f},n[t]=x):(x.id=u.id,x.object=u,x.geometry=m,x.material=v,x.materialVariant=a(u),x.groupOrder=M,x.renderOrder=u.renderOrder,x.z=p,x.group=f),t++,x}function c(u,m,v,M,p,f,x){x.reversedDepth===!0&&(p=-p);const A=o(u,m,v,M,p,f);v.transmission>0?i.push(A):v.transparent===!0?s.push(A):e.push(A)}function l(u,m,v,M,p,f){const x=o(u,m,v,M,p,f);v.transmission>0?i.unshift(x):v.transparent===!0?s.unshift(x):e.unshift(x)}function h(u,m){e.length>1&&e.sort(u||ZS),i.length>1&&i.sort(m||dd),s.length>1&&s.sort(m||dd)}function d(){for(let u=t,m=n.length;u<m;u++){const v=n[u];if(v.id===null)break;v.id=null,v.object=null,v.geometry=null,v.material=null,v.group=null}}return{opaque:e,transmissive:i,transparent:s,init:r,push:c,unshift:l,finish:d,sort:h}}function JS(){let n=new WeakMap;function t(i,s){const r=n.get(i);let a;return r===void 0?(a=new fd,n.set(i,[a])):s>=r.length?(a=new fd,r.push(a)):a=r[s],a}function e(){n=new WeakMap}return{get:t,dispose:e}}function QS(){const n={};return{get:function(t){if(n[t.id]!==void 0)return n[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={direction:new V,color:new le};break;case"SpotLight":e={position:new V,direction:new V,color:new le,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":e={position:new V,color:new le,distance:0,decay:0};break;case"HemisphereLight":e={direction:new V,skyColor:new le,groundColor:new le};break;case"RectAreaLight":e={color:new le,position:new V,halfWidth:new V,halfHeight:new V};break}return n[t.id]=e,e}}}function jS(){const n={};return{get:function(t){if(n[t.id]!==void 0)return n[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Jt};break;case"SpotLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Jt};break;case"PointLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Jt,shadowCameraNear:1,shadowCameraFar:1e3};break}return n[t.id]=e,e}}}let tM=0;function eM(n,t){return(t.castShadow?2:0)-(n.castShadow?2:0)+(t.map?1:0)-(n.map?1:0)}function nM(n){const t=new QS,e=jS(),i={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let l=0;l<9;l++)i.probe.push(new V);const s=new V,r=new Le,a=new Le;function o(l){let h=0,d=0,u=0;for(let I=0;I<9;I++)i.probe[I].set(0,0,0);let m=0,v=0,M=0,p=0,f=0,x=0,A=0,y=0,R=0,E=0,g=0,T=0,z=0,U=0;l.sort(eM);for(let I=0,B=l.length;I<B;I++){const L=l[I],G=L.color,Y=L.intensity,k=L.distance;let lt=null;if(L.shadow&&L.shadow.map&&(L.shadow.map.texture.format===Ws?lt=L.shadow.map.texture:lt=L.shadow.map.depthTexture||L.shadow.map.texture),L.isAmbientLight)h+=G.r*Y,d+=G.g*Y,u+=G.b*Y;else if(L.isLightProbe){for(let K=0;K<9;K++)i.probe[K].addScaledVector(L.sh.coefficients[K],Y);U++}else if(L.isSunLight){const K=t.get(L);if(K.color.copy(L.color).multiplyScalar(L.intensity),L.castShadow){const Q=L.shadow,nt=e.get(L);nt.shadowIntensity=Q.intensity,nt.shadowBias=Q.bias,nt.shadowNormalBias=Q.normalBias,nt.shadowRadius=Q.radius,nt.shadowMapSize.copy(Q.mapSize).multiply(Q.getFrameExtents()),i.sunShadow[v]=nt,i.sunShadowMap[v]=lt;const ut=Q.getViewportCount();for(let ot=0;ot<ut;ot++)i.sunShadowMatrix[M+ot]=Q.getMatrix(ot),i.sunShadowCascade[M+ot]=Q._cascadeData[ot];M+=ut,v++}i.sun[m]=K,m++}else if(L.isDirectionalLight){const K=t.get(L);if(K.color.copy(L.color).multiplyScalar(L.intensity),L.castShadow){const Q=L.shadow,nt=e.get(L);nt.shadowIntensity=Q.intensity,nt.shadowBias=Q.bias,nt.shadowNormalBias=Q.normalBias,nt.shadowRadius=Q.radius,nt.shadowMapSize=Q.mapSize,i.directionalShadow[p]=nt,i.directionalShadowMap[p]=lt,i.directionalShadowMatrix[p]=L.shadow.matrix,R++}i.directional[p]=K,p++}else if(L.isSpotLight){const K=t.get(L);K.position.setFromMatrixPosition(L.matrixWorld),K.color.copy(G).multiplyScalar(Y),K.distance=k,K.coneCos=Math.cos(L.angle),K.penumbraCos=Math.cos(L.angle*(1-L.penumbra)),K.decay=L.decay,i.spot[x]=K;const Q=L.shadow;if(L.map&&(i.spotLightMap[T]=L.map,T++,Q.updateMatrices(L),L.castShadow&&z++),i.spotLightMatrix[x]=Q.matrix,L.castShadow){const nt=e.get(L);nt.shadowIntensity=Q.intensity,nt.shadowBias=Q.bias,nt.shadowNormalBias=Q.normalBias,nt.shadowRadius=Q.radius,nt.shadowMapSize=Q.mapSize,i.spotShadow[x]=nt,i.spotShadowMap[x]=lt,g++}x++}else if(L.isRectAreaLight){const K=t.get(L);K.color.copy(G).multiplyScalar(Y),K.halfWidth.set(L.width*.5,0,0),K.halfHeight.set(0,L.height*.5,0),i.rectArea[A]=K,A++}else if(L.isPointLight){const K=t.get(L);if(K.color.copy(L.color).multiplyScalar(L.intensity),K.distance=L.distance,K.decay=L.decay,L.castShadow){const Q=L.shadow,nt=e.get(L);nt.shadowIntensity=Q.intensity,nt.shadowBias=Q.bias,nt.shadowNormalBias=Q.normalBias,nt.shadowRadius=Q.radius,nt.shadowMapSize=Q.mapSize,nt.shadowCameraNear=Q.camera.near,nt.shadowCameraFar=Q.camera.far,i.pointShadow[f]=nt,i.pointShadowMap[f]=lt,i.pointShadowMatrix[f]=L.shadow.matrix,E++}i.point[f]=K,f++}else if(L.isHemisphereLight){const K=t.get(L);K.skyColor.copy(L.color).multiplyScalar(Y),K.groundColor.copy(L.groundColor).multiplyScalar(Y),i.hemi[y]=K,y++}}A>0&&(n.has("OES_texture_float_linear")===!0?(i.rectAreaLTC1=Lt.LTC_FLOAT_1,i.rectAreaLTC2=Lt.LTC_FLOAT_2):(i.rectAreaLTC1=Lt.LTC_HALF_1,i.rectAreaLTC2=Lt.LTC_HALF_2)),i.ambient[0]=h,i.ambient[1]=d,i.ambient[2]=u;const D=i.hash;(D.sunLength!==m||D.directionalLength!==p||D.pointLength!==f||D.spotLength!==x||D.rectAreaLength!==A||D.hemiLength!==y||D.numSunShadows!==v||D.numDirectionalShadows!==R||D.numPointShadows!==E||D.numSpotShadows!==g||D.numSpotMaps!==T||D.numLightProbes!==U)&&(i.sun.length=m,i.directional.length=p,i.spot.length=x,i.rectArea.length=A,i.point.length=f,i.hemi.length=y,i.sunShadow.length=v,i.sunShadowMap.length=v,i.sunShadowMatrix.length=M,i.sunShadowCascade.length=M,i.directionalShadow.length=R,i.directionalShadowMap.length=R,i.directionalShadowMatrix.length=R,i.pointShadow.length=E,i.pointShadowMap.length=E,i.pointShadowMatrix.length=E,i.spotShadow.length=g,i.spotShadowMap.length=g,i.spotLightMatrix.length=g+T-z,i.spotLightMap.length=T,i.numSpotLightShadowsWithMaps=z,i.numLightProbes=U,D.sunLength=m,D.directionalLength=p,D.pointLength=f,D.spotLength=x,D.rectAreaLength=A,D.hemiLength=y,D.numSunShadows=v,D.numDirectionalShadows=R,D.numPointShadows=E,D.numSpotShadows=g,D.numSpotMaps=T,D.numLightProbes=U,i.version=tM++)}function c(l,h){let d=0,u=0,m=0,v=0,M=0,p=0;const f=h.matrixWorldInverse;for(let x=0,A=l.length;x<A;x++){const y=l[x];if(y.isSunLight){const R=i.sun[d];R.direction.setFromMatrixPosition(y.matrixWorld),R.direction.transformDirection(f),d++}else if(y.isDirectionalLight){const R=i.directional[u];R.direction.setFromMatrixPosition(y.matrixWorld),s.setFromMatrixPosition(y.target.matrixWorld),R.direction.sub(s),R.direction.transformDirection(f),u++}else if(y.isSpotLight){const R=i.spot[v];R.position.setFromMatrixPosition(y.matrixWorld),R.position.applyMatrix4(f),R.direction.setFromMatrixPosition(y.matrixWorld),s.setFromMatrixPosition(y.target.matrixWorld),R.direction.sub(s),R.direction.transformDirection(f),v++}else if(y.isRectAreaLight){const R=i.rectArea[M];R.position.setFromMatrixPosition(y.matrixWorld),R.position.applyMatrix4(f),a.identity(),r.copy(y.matrixWorld),r.premultiply(f),a.extractRotation(r),R.halfWidth.set(y.width*.5,0,0),R.halfHeight.set(0,y.height*.5,0),R.halfWidth.applyMatrix4(a),R.halfHeight.applyMatrix4(a),M++}else if(y.isPointLight){const R=i.point[m];R.position.setFromMatrixPosition(y.matrixWorld),R.position.applyMatrix4(f),m++}else if(y.isHemisphereLight){const R=i.hemi[p];R.direction.setFromMatrixPosition(y.matrixWorld),R.direction.transformDirection(f),p++}}}return{setup:o,setupView:c,state:i}}function pd(n){const t=new nM(n),e=[],i=[],s=[];function r(d){h.camera=d,e.length=0,i.length=0,s.length=0}function a(d){d.isLightProbeGrid?s.push(d):e.push(d)}function o(d){i.push(d)}function c(){t.setup(e),s.sort((d,u)=>d.priority-u.priority||d.id-u.id)}function l(d){t.setupView(e,d)}const h={lightsArray:e,shadowsArray:i,lightProbeGridArray:s,camera:null,lights:t,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:h,setupLights:c,setupLightsView:l,pushLight:a,pushShadow:o}}function iM(n){let t=new WeakMap;function e(s,r=0){const a=t.get(s);let o;return a===void 0?(o=new pd(n),t.set(s,[o])):r>=a.length?(o=new pd(n),a.push(o)):o=a[r],o}function i(){t=new WeakMap}return{get:e,dispose:i}}const sM=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,rM=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,aM=[new V(1,0,0),new V(-1,0,0),new V(0,1,0),new V(0,-1,0),new V(0,0,1),new V(0,0,-1)],oM=[new V(0,-1,0),new V(0,-1,0),new V(0,0,1),new V(0,0,-1),new V(0,-1,0),new V(0,-1,0)],md=new Le,Qr=new V,Bl=new V;function lM(n,t,e){let i=new Sa;const s=new Jt,r=new Jt,a=new Qe,o=new __,c=new v_,l={},h=e.maxTextureSize,d={[Es]:Vn,[Vn]:Es,[ci]:ci},u=new As({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new Jt},radius:{value:4}},vertexShader:sM,fragmentShader:rM}),m=u.clone();m.defines.HORIZONTAL_PASS=1;const v=new ln;v.setAttribute("position",new ns(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));const M=new bn(v,u),p=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=_o;let f=this.type;this.render=function(E,g,T){if(p.enabled===!1||p.autoUpdate===!1&&p.needsUpdate===!1||E.length===0)return;this.type===ig&&(Kt("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=_o);const z=n.getRenderTarget(),U=n.getActiveCubeFace(),D=n.getActiveMipmapLevel(),I=n.state;I.setBlending(Er),I.buffers.depth.getReversed()===!0?I.buffers.color.setClear(0,0,0,0):I.buffers.color.setClear(1,1,1,1),I.buffers.depth.setTest(!0),I.setScissorTest(!1);const B=f!==this.type;B&&g.traverse(function(L){L.material&&(Array.isArray(L.material)?L.material.forEach(G=>G.needsUpdate=!0):L.material.needsUpdate=!0)});for(let L=0,G=E.length;L<G;L++){const Y=E[L],k=Y.shadow;if(k===void 0){Kt("WebGLShadowMap:",Y,"has no shadow.");continue}if(k.autoUpdate===!1&&k.needsUpdate===!1)continue;s.copy(k.mapSize);const lt=k.getFrameExtents();s.multiply(lt),r.copy(k.mapSize),(s.x>h||s.y>h)&&(s.x>h&&(r.x=Math.floor(h/lt.x),s.x=r.x*lt.x,k.mapSize.x=r.x),s.y>h&&(r.y=Math.floor(h/lt.y),s.y=r.y*lt.y,k.mapSize.y=r.y));const K=n.state.buffers.depth.getReversed();if(k.camera._reversedDepth=K,k.map===null||B===!0){if(k.map!==null&&(k.map.depthTexture!==null&&(k.map.depthTexture.dispose(),k.map.depthTexture=null),k.map.dispose()),this.type===sa){if(Y.isPointLight){Kt("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}k.map=new hi(s.x,s.y,{format:Ws,type:Hi,minFilter:zn,magFilter:zn,generateMipmaps:!1}),k.map.texture.name=Y.name+".shadowMap",k.map.depthTexture=new Rr(s.x,s.y,Bi),k.map.depthTexture.name=Y.name+".shadowMapDepth",k.map.depthTexture.format=bs,k.map.depthTexture.compareFunction=null,k.map.depthTexture.minFilter=wn,k.map.depthTexture.magFilter=wn}else Y.isPointLight?(k.map=new Ah(s.x),k.map.depthTexture=new jf(s.x,ki)):(k.map=new hi(s.x,s.y),k.map.depthTexture=new Rr(s.x,s.y,ki)),k.map.depthTexture.name=Y.name+".shadowMap",k.map.depthTexture.format=bs,this.type===_o?(k.map.depthTexture.compareFunction=K?Wf:Vf,k.map.depthTexture.minFilter=zn,k.map.depthTexture.magFilter=zn):(k.map.depthTexture.compareFunction=null,k.map.depthTexture.minFilter=wn,k.map.depthTexture.magFilter=wn);k.camera.updateProjectionMatrix()}k.map.isWebGLCubeRenderTarget!==!0&&(k.map.width!==s.x||k.map.height!==s.y)&&k.map.setSize(s.x,s.y);const Q=k.map.isWebGLCubeRenderTarget?6:k.getViewportCount();Y.isPointLight!==!0&&k.updateMatrices(Y,T);const nt=(k.camera.layers.mask&4294967294)!==0?k.camera.layers:T.layers;for(let ut=0;ut<Q;ut++){const ot=k.getCamera(ut);if(Y.isPointLight){const j=k.camera,pt=k.matrix,_t=Y.distance||j.far;_t!==j.far&&(j.far=_t,j.updateProjectionMatrix()),Qr.setFromMatrixPosition(Y.matrixWorld),j.position.copy(Qr),Bl.copy(j.position),Bl.add(aM[ut]),j.up.copy(oM[ut]),j.lookAt(Bl),j.updateMatrixWorld(),pt.makeTranslation(-Qr.x,-Qr.y,-Qr.z),md.multiplyMatrices(j.projectionMatrix,j.matrixWorldInverse),k._frustum.setFromProjectionMatrix(md,j.coordinateSystem,j.reversedDepth)}if(k.map.isWebGLCubeRenderTarget)n.setRenderTarget(k.map,ut),n.clear();else{ut===0&&(n.setRenderTarget(k.map),n.clear());const j=k.getViewport(ut);a.set(r.x*j.x,r.y*j.y,r.x*j.z,r.y*j.w),I.viewport(a)}i=k.getFrustum(ut),y(g,T,ot,Y,nt,this.type)}k.isPointLightShadow!==!0&&this.type===sa&&x(k,T),k.needsUpdate=!1}f=this.type,p.needsUpdate=!1,n.setRenderTarget(z,U,D)};function x(E,g){const T=t.update(M);u.defines.VSM_SAMPLES!==E.blurSamples&&(u.defines.VSM_SAMPLES=E.blurSamples,m.defines.VSM_SAMPLES=E.blurSamples,u.needsUpdate=!0,m.needsUpdate=!0),E.mapPass===null?E.mapPass=new hi(s.x,s.y,{format:Ws,type:Hi}):(E.mapPass.width!==E.map.width||E.mapPass.height!==E.map.height)&&E.mapPass.setSize(E.map.width,E.map.height),u.uniforms.shadow_pass.value=E.map.depthTexture,u.uniforms.resolution.value.set(E.map.width,E.map.height),u.uniforms.radius.value=E.radius,n.setRenderTarget(E.mapPass),n.clear(),n.renderBufferDirect(g,null,T,u,M,null),m.uniforms.shadow_pass.value=E.mapPass.texture,m.uniforms.resolution.value.set(E.map.width,E.map.height),m.uniforms.radius.value=E.radius,n.setRenderTarget(E.map),n.clear(),n.renderBufferDirect(g,null,T,m,M,null)}function A(E,g,T,z){let U=null;const D=T.isPointLight===!0?E.customDistanceMaterial:E.customDepthMaterial;if(D!==void 0)U=D;else if(U=T.isPointLight===!0?c:o,n.localClippingEnabled&&g.clipShadows===!0&&Array.isArray(g.clippingPlanes)&&g.clippingPlanes.length!==0||g.displacementMap&&g.displacementScale!==0||g.alphaMap&&g.alphaTest>0||g.map&&g.alphaTest>0||g.alphaToCoverage===!0){const I=U.uuid,B=g.uuid;let L=l[I];L===void 0&&(L={},l[I]=L);let G=L[B];G===void 0&&(G=U.clone(),L[B]=G,g.addEventListener("dispose",R)),U=G}if(U.visible=g.visible,U.wireframe=g.wireframe,z===sa?U.side=g.shadowSide!==null?g.shadowSide:g.side:U.side=g.shadowSide!==null?g.shadowSide:d[g.side],U.alphaMap=g.alphaMap,U.alphaTest=g.alphaToCoverage===!0?.5:g.alphaTest,U.map=g.map,U.clipShadows=g.clipShadows,U.clippingPlanes=g.clippingPlanes,U.clipIntersection=g.clipIntersection,U.displacementMap=g.displacementMap,U.displacementScale=g.displacementScale,U.displacementBias=g.displacementBias,U.wireframeLinewidth=g.wireframeLinewidth,U.linewidth=g.linewidth,T.isPointLight===!0&&U.isMeshDistanceMaterial===!0){const I=n.properties.get(U);I.light=T}return U}function y(E,g,T,z,U,D){if(E.visible===!1)return;if(E.layers.test(U)&&(E.isMesh||E.isLine||E.isPoints)&&(E.castShadow||E.receiveShadow&&D===sa)&&(!E.frustumCulled||E.intersectsFrustum(i))){E.modelViewMatrix.multiplyMatrices(T.matrixWorldInverse,E.matrixWorld);const L=t.update(E),G=E.material;if(Array.isArray(G)){const Y=L.groups;for(let k=0,lt=Y.length;k<lt;k++){const K=Y[k],Q=G[K.materialIndex];if(Q&&Q.visible){const nt=A(E,Q,z,D);E.onBeforeShadow(n,E,g,T,L,nt,K),n.renderBufferDirect(T,null,L,nt,E,K),E.onAfterShadow(n,E,g,T,L,nt,K)}}}else if(G.visible){const Y=A(E,G,z,D);E.onBeforeShadow(n,E,g,T,L,Y,null),n.renderBufferDirect(T,null,L,Y,E,null),E.onAfterShadow(n,E,g,T,L,Y,null)}}const B=E.children;for(let L=0,G=B.length;L<G;L++)y(B[L],g,T,z,U,D)}function R(E){E.target.removeEventListener("dispose",R);for(const T in l){const z=l[T],U=E.target.uuid;U in z&&(z[U].dispose(),delete z[U])}}}function cM(n,t){function e(){let F=!1;const st=new Qe;let et=null;const Et=new Qe(0,0,0,0);return{setMask:function(mt){et!==mt&&!F&&(n.colorMask(mt,mt,mt,mt),et=mt)},setLocked:function(mt){F=mt},setClear:function(mt,St,Ht,Yt,ct){ct===!0&&(mt*=Yt,St*=Yt,Ht*=Yt),st.set(mt,St,Ht,Yt),Et.equals(st)===!1&&(n.clearColor(mt,St,Ht,Yt),Et.copy(st))},reset:function(){F=!1,et=null,Et.set(-1,0,0,0)}}}function i(){let F=!1,st=!1,et=null,Et=null,mt=null;return{setReversed:function(St){if(st!==St){const Ht=t.get("EXT_clip_control");St?Ht.clipControlEXT(Ht.LOWER_LEFT_EXT,Ht.ZERO_TO_ONE_EXT):Ht.clipControlEXT(Ht.LOWER_LEFT_EXT,Ht.NEGATIVE_ONE_TO_ONE_EXT),st=St;const Yt=mt;mt=null,this.setClear(Yt)}},getReversed:function(){return st},setTest:function(St){St?Mt(n.DEPTH_TEST):Gt(n.DEPTH_TEST)},setMask:function(St){et!==St&&!F&&(n.depthMask(St),et=St)},setFunc:function(St){if(st&&(St=Og[St]),Et!==St){switch(St){case lc:n.depthFunc(n.NEVER);break;case cc:n.depthFunc(n.ALWAYS);break;case hc:n.depthFunc(n.LESS);break;case ga:n.depthFunc(n.LEQUAL);break;case uc:n.depthFunc(n.EQUAL);break;case dc:n.depthFunc(n.GEQUAL);break;case fc:n.depthFunc(n.GREATER);break;case pc:n.depthFunc(n.NOTEQUAL);break;default:n.depthFunc(n.LEQUAL)}Et=St}},setLocked:function(St){F=St},setClear:function(St){mt!==St&&(mt=St,st&&(St=1-St),n.clearDepth(St))},reset:function(){F=!1,et=null,Et=null,mt=null,st=!1}}}function s(){let F=!1,st=null,et=null,Et=null,mt=null,St=null,Ht=null,Yt=null,ct=null;return{setTest:function(Ft){F||(Ft?Mt(n.STENCIL_TEST):Gt(n.STENCIL_TEST))},setMask:function(Ft){st!==Ft&&!F&&(n.stencilMask(Ft),st=Ft)},setFunc:function(Ft,qt,At){(et!==Ft||Et!==qt||mt!==At)&&(n.stencilFunc(Ft,qt,At),et=Ft,Et=qt,mt=At)},setOp:function(Ft,qt,At){(St!==Ft||Ht!==qt||Yt!==At)&&(n.stencilOp(Ft,qt,At),St=Ft,Ht=qt,Yt=At)},setLocked:function(Ft){F=Ft},setClear:function(Ft){ct!==Ft&&(n.clearStencil(Ft),ct=Ft)},reset:function(){F=!1,st=null,et=null,Et=null,mt=null,St=null,Ht=null,Yt=null,ct=null}}}const r=new e,a=new i,o=new s;let c={};const l=new WeakMap;let h={},d={},u={},m=new WeakMap,v=[],M=null,p=!1,f=null,x=null,A=null,y=null,R=null,E=null,g=null,T=new le(0,0,0),z=0,U=!1,D=null,I=null,B=null,L=null,G=null;const Y=n.getParameter(n.MAX_COMBINED_TEXTURE_IMAGE_UNITS);let k=!1,lt=0;const K=n.getParameter(n.VERSION);K.indexOf("WebGL")!==-1?(lt=parseFloat(/^WebGL (\d)/.exec(K)[1]),k=lt>=1):K.indexOf("OpenGL ES")!==-1&&(lt=parseFloat(/^OpenGL ES (\d)/.exec(K)[1]),k=lt>=2);let Q=null,nt={};const ut=n.getParameter(n.SCISSOR_BOX),ot=n.getParameter(n.VIEWPORT),j=new Qe().fromArray(ut),pt=new Qe().fromArray(ot);function _t(F,st,et,Et){const mt=new Uint8Array(4),St=n.createTexture();n.bindTexture(F,St),n.texParameteri(F,n.TEXTURE_MIN_FILTER,n.NEAREST),n.texParameteri(F,n.TEXTURE_MAG_FILTER,n.NEAREST);for(let Ht=0;Ht<et;Ht++)F===n.TEXTURE_3D||F===n.TEXTURE_2D_ARRAY?n.texImage3D(st,0,n.RGBA,1,1,Et,0,n.RGBA,n.UNSIGNED_BYTE,mt):n.texImage2D(st+Ht,0,n.RGBA,1,1,0,n.RGBA,n.UNSIGNED_BYTE,mt);return St}const Tt={};Tt[n.TEXTURE_2D]=_t(n.TEXTURE_2D,n.TEXTURE_2D,1),Tt[n.TEXTURE_CUBE_MAP]=_t(n.TEXTURE_CUBE_MAP,n.TEXTURE_CUBE_MAP_POSITIVE_X,6),Tt[n.TEXTURE_2D_ARRAY]=_t(n.TEXTURE_2D_ARRAY,n.TEXTURE_2D_ARRAY,1,1),Tt[n.TEXTURE_3D]=_t(n.TEXTURE_3D,n.TEXTURE_3D,1,1),r.setClear(0,0,0,1),a.setClear(1),o.setClear(0),Mt(n.DEPTH_TEST),a.setFunc(ga),je(!1),Re(uu),Mt(n.CULL_FACE),He(Er);function Mt(F){h[F]!==!0&&(n.enable(F),h[F]=!0)}function Gt(F){h[F]!==!1&&(n.disable(F),h[F]=!1)}function ee(F,st){return u[F]!==st?(n.bindFramebuffer(F,st),u[F]=st,F===n.DRAW_FRAMEBUFFER&&(u[n.FRAMEBUFFER]=st),F===n.FRAMEBUFFER&&(u[n.DRAW_FRAMEBUFFER]=st),!0):!1}function kt(F,st){let et=v,Et=!1;if(F){et=m.get(st),et===void 0&&(et=[],m.set(st,et));const mt=F.textures;if(et.length!==mt.length||et[0]!==n.COLOR_ATTACHMENT0){for(let St=0,Ht=mt.length;St<Ht;St++)et[St]=n.COLOR_ATTACHMENT0+St;et.length=mt.length,Et=!0}}else et[0]!==n.BACK&&(et[0]=n.BACK,Et=!0);Et&&n.drawBuffers(et)}function oe(F){return M!==F?(n.useProgram(F),M=F,!0):!1}const se={[vr]:n.FUNC_ADD,[rg]:n.FUNC_SUBTRACT,[ag]:n.FUNC_REVERSE_SUBTRACT};se[og]=n.MIN,se[lg]=n.MAX;const Qt={[cg]:n.ZERO,[hg]:n.ONE,[ug]:n.SRC_COLOR,[wf]:n.SRC_ALPHA,[_g]:n.SRC_ALPHA_SATURATE,[mg]:n.DST_COLOR,[fg]:n.DST_ALPHA,[dg]:n.ONE_MINUS_SRC_COLOR,[Tf]:n.ONE_MINUS_SRC_ALPHA,[gg]:n.ONE_MINUS_DST_COLOR,[pg]:n.ONE_MINUS_DST_ALPHA,[vg]:n.CONSTANT_COLOR,[xg]:n.ONE_MINUS_CONSTANT_COLOR,[Sg]:n.CONSTANT_ALPHA,[Mg]:n.ONE_MINUS_CONSTANT_ALPHA};function He(F,st,et,Et,mt,St,Ht,Yt,ct,Ft){if(F===Er){p===!0&&(Gt(n.BLEND),p=!1);return}if(p===!1&&(Mt(n.BLEND),p=!0),F!==sg){if(F!==f||Ft!==U){if((x!==vr||R!==vr)&&(n.blendEquation(n.FUNC_ADD),x=vr,R=vr),Ft)switch(F){case ha:n.blendFuncSeparate(n.ONE,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case du:n.blendFunc(n.ONE,n.ONE);break;case fu:n.blendFuncSeparate(n.ZERO,n.ONE_MINUS_SRC_COLOR,n.ZERO,n.ONE);break;case pu:n.blendFuncSeparate(n.DST_COLOR,n.ONE_MINUS_SRC_ALPHA,n.ZERO,n.ONE);break;default:ve("WebGLState: Invalid blending: ",F);break}else switch(F){case ha:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case du:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE,n.ONE,n.ONE);break;case fu:ve("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case pu:ve("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:ve("WebGLState: Invalid blending: ",F);break}A=null,y=null,E=null,g=null,T.set(0,0,0),z=0,f=F,U=Ft}return}mt=mt||st,St=St||et,Ht=Ht||Et,(st!==x||mt!==R)&&(n.blendEquationSeparate(se[st],se[mt]),x=st,R=mt),(et!==A||Et!==y||St!==E||Ht!==g)&&(n.blendFuncSeparate(Qt[et],Qt[Et],Qt[St],Qt[Ht]),A=et,y=Et,E=St,g=Ht),(Yt.equals(T)===!1||ct!==z)&&(n.blendColor(Yt.r,Yt.g,Yt.b,ct),T.copy(Yt),z=ct),f=F,U=!1}function Ue(F,st){F.side===ci?Gt(n.CULL_FACE):Mt(n.CULL_FACE);let et=F.side===Vn;st&&(et=!et),je(et),F.blending===ha&&F.transparent===!1?He(Er):He(F.blending,F.blendEquation,F.blendSrc,F.blendDst,F.blendEquationAlpha,F.blendSrcAlpha,F.blendDstAlpha,F.blendColor,F.blendAlpha,F.premultipliedAlpha),a.setFunc(F.depthFunc),a.setTest(F.depthTest),a.setMask(F.depthWrite),r.setMask(F.colorWrite);const Et=F.stencilWrite;o.setTest(Et),Et&&(o.setMask(F.stencilWriteMask),o.setFunc(F.stencilFunc,F.stencilRef,F.stencilFuncMask),o.setOp(F.stencilFail,F.stencilZFail,F.stencilZPass)),ge(F.polygonOffset,F.polygonOffsetFactor,F.polygonOffsetUnits),F.alphaToCoverage===!0?Mt(n.SAMPLE_ALPHA_TO_COVERAGE):Gt(n.SAMPLE_ALPHA_TO_COVERAGE)}function je(F){D!==F&&(F?n.frontFace(n.CW):n.frontFace(n.CCW),D=F)}function Re(F){F!==eg?(Mt(n.CULL_FACE),F!==I&&(F===uu?n.cullFace(n.BACK):F===ng?n.cullFace(n.FRONT):n.cullFace(n.FRONT_AND_BACK))):Gt(n.CULL_FACE),I=F}function _n(F){F!==B&&(k&&n.lineWidth(F),B=F)}function ge(F,st,et){F?(Mt(n.POLYGON_OFFSET_FILL),(L!==st||G!==et)&&(L=st,G=et,a.getReversed()&&(st=-st,et=-et),n.polygonOffset(st,et))):Gt(n.POLYGON_OFFSET_FILL)}function cn(F){F?Mt(n.SCISSOR_TEST):Gt(n.SCISSOR_TEST)}function Xe(F){F===void 0&&(F=n.TEXTURE0+Y-1),Q!==F&&(n.activeTexture(F),Q=F)}function tn(F,st,et){et===void 0&&(Q===null?et=n.TEXTURE0+Y-1:et=Q);let Et=nt[et];Et===void 0&&(Et={type:void 0,texture:void 0},nt[et]=Et),(Et.type!==F||Et.texture!==st)&&(Q!==et&&(n.activeTexture(et),Q=et),n.bindTexture(F,st||Tt[F]),Et.type=F,Et.texture=st)}function O(){const F=nt[Q];F!==void 0&&F.type!==void 0&&(n.bindTexture(F.type,null),F.type=void 0,F.texture=void 0)}function Rt(){try{n.compressedTexImage2D(...arguments)}catch(F){ve("WebGLState:",F)}}function Xt(){try{n.compressedTexImage3D(...arguments)}catch(F){ve("WebGLState:",F)}}function ne(){try{n.texSubImage2D(...arguments)}catch(F){ve("WebGLState:",F)}}function yt(){try{n.texSubImage3D(...arguments)}catch(F){ve("WebGLState:",F)}}function De(){try{n.compressedTexSubImage2D(...arguments)}catch(F){ve("WebGLState:",F)}}function zt(){try{n.compressedTexSubImage3D(...arguments)}catch(F){ve("WebGLState:",F)}}function Wt(){try{n.texStorage2D(...arguments)}catch(F){ve("WebGLState:",F)}}function C(){try{n.texStorage3D(...arguments)}catch(F){ve("WebGLState:",F)}}function S(){try{n.texImage2D(...arguments)}catch(F){ve("WebGLState:",F)}}function X(){try{n.texImage3D(...arguments)}catch(F){ve("WebGLState:",F)}}function ht(F){return d[F]!==void 0?d[F]:n.getParameter(F)}function rt(F,st){d[F]!==st&&(n.pixelStorei(F,st),d[F]=st)}function gt(F){j.equals(F)===!1&&(n.scissor(F.x,F.y,F.z,F.w),j.copy(F))}function vt(F){pt.equals(F)===!1&&(n.viewport(F.x,F.y,F.z,F.w),pt.copy(F))}function tt(F,st){let et=l.get(st);et===void 0&&(et=new WeakMap,l.set(st,et));let Et=et.get(F);Et===void 0&&(Et=n.getUniformBlockIndex(st,F.name),n.uniformBlockBinding(st,Et,Et),et.set(F,Et))}function it(F,st,et){const mt=l.get(st).get(F);c[mt]!==et&&(n.bindBufferBase(n.UNIFORM_BUFFER,mt,et),c[mt]=et)}function ft(){n.disable(n.BLEND),n.disable(n.CULL_FACE),n.disable(n.DEPTH_TEST),n.disable(n.POLYGON_OFFSET_FILL),n.disable(n.SCISSOR_TEST),n.disable(n.STENCIL_TEST),n.disable(n.SAMPLE_ALPHA_TO_COVERAGE),n.blendEquation(n.FUNC_ADD),n.blendFunc(n.ONE,n.ZERO),n.blendFuncSeparate(n.ONE,n.ZERO,n.ONE,n.ZERO),n.blendColor(0,0,0,0),n.colorMask(!0,!0,!0,!0),n.clearColor(0,0,0,0),n.depthMask(!0),n.depthFunc(n.LESS),a.setReversed(!1),n.clearDepth(1),n.stencilMask(4294967295),n.stencilFunc(n.ALWAYS,0,4294967295),n.stencilOp(n.KEEP,n.KEEP,n.KEEP),n.clearStencil(0),n.cullFace(n.BACK),n.frontFace(n.CCW),n.polygonOffset(0,0),n.activeTexture(n.TEXTURE0),n.bindFramebuffer(n.FRAMEBUFFER,null),n.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),n.bindFramebuffer(n.READ_FRAMEBUFFER,null),n.useProgram(null),n.lineWidth(1),n.scissor(0,0,n.canvas.width,n.canvas.height),n.viewport(0,0,n.canvas.width,n.canvas.height),n.pixelStorei(n.PACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,!1),n.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),n.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,n.BROWSER_DEFAULT_WEBGL),n.pixelStorei(n.PACK_ROW_LENGTH,0),n.pixelStorei(n.PACK_SKIP_PIXELS,0),n.pixelStorei(n.PACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_ROW_LENGTH,0),n.pixelStorei(n.UNPACK_IMAGE_HEIGHT,0),n.pixelStorei(n.UNPACK_SKIP_PIXELS,0),n.pixelStorei(n.UNPACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_SKIP_IMAGES,0),h={},d={},Q=null,nt={},u={},c={},m=new WeakMap,v=[],M=null,p=!1,f=null,x=null,A=null,y=null,R=null,E=null,g=null,T=new le(0,0,0),z=0,U=!1,D=null,I=null,B=null,L=null,G=null,j.set(0,0,n.canvas.width,n.canvas.height),pt.set(0,0,n.canvas.width,n.canvas.height),r.reset(),a.reset(),o.reset()}return{buffers:{color:r,depth:a,stencil:o},enable:Mt,disable:Gt,bindFramebuffer:ee,drawBuffers:kt,useProgram:oe,setBlending:He,setMaterial:Ue,setFlipSided:je,setCullFace:Re,setLineWidth:_n,setPolygonOffset:ge,setScissorTest:cn,activeTexture:Xe,bindTexture:tn,unbindTexture:O,compressedTexImage2D:Rt,compressedTexImage3D:Xt,texImage2D:S,texImage3D:X,pixelStorei:rt,getParameter:ht,updateUBOMapping:tt,uniformBlockBinding:it,texStorage2D:Wt,texStorage3D:C,texSubImage2D:ne,texSubImage3D:yt,compressedTexSubImage2D:De,compressedTexSubImage3D:zt,scissor:gt,viewport:vt,reset:ft}}function hM(n,t,e,i,s,r,a){const o=t.has("WEBGL_multisampled_render_to_texture")?t.get("WEBGL_multisampled_render_to_texture"):null,c=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),l=new Jt,h=new WeakMap,d=new Set;let u;const m=new WeakMap,v=new Set,M=new FinalizationRegistry(C=>v.delete(C));let p=!1;try{p=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function f(C,S){return p?new OffscreenCanvas(C,S):Co("canvas")}function x(C,S,X){let ht=1;const rt=Wt(C);if((rt.width>X||rt.height>X)&&(ht=X/Math.max(rt.width,rt.height)),ht<1)if(typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&C instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&C instanceof ImageBitmap||typeof VideoFrame<"u"&&C instanceof VideoFrame){const gt=Math.floor(ht*rt.width),vt=Math.floor(ht*rt.height);u===void 0&&(u=f(gt,vt));const tt=S?f(gt,vt):u;return tt.width=gt,tt.height=vt,tt.getContext("2d").drawImage(C,0,0,gt,vt),Kt("WebGLRenderer: Texture has been resized from ("+rt.width+"x"+rt.height+") to ("+gt+"x"+vt+")."),tt}else return"data"in C&&Kt("WebGLRenderer: Image in DataTexture is too big ("+rt.width+"x"+rt.height+")."),C;return C}function A(C){return C.generateMipmaps}function y(C){n.generateMipmap(C)}function R(C){return C.isWebGLCubeRenderTarget?n.TEXTURE_CUBE_MAP:C.isWebGL3DRenderTarget?n.TEXTURE_3D:C.isWebGLArrayRenderTarget||C.isCompressedArrayTexture?n.TEXTURE_2D_ARRAY:n.TEXTURE_2D}function E(C,S,X,ht,rt,gt=!1){if(C!==null){if(n[C]!==void 0)return n[C];Kt("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+C+"'")}let vt;ht&&(vt=t.get("EXT_texture_norm16"),vt||Kt("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let tt=S;if(S===n.RED&&(X===n.FLOAT&&(tt=n.R32F),X===n.HALF_FLOAT&&(tt=n.R16F),X===n.UNSIGNED_BYTE&&(tt=n.R8),X===n.UNSIGNED_SHORT&&vt&&(tt=vt.R16_EXT),X===n.SHORT&&vt&&(tt=vt.R16_SNORM_EXT)),S===n.RED_INTEGER&&(X===n.UNSIGNED_BYTE&&(tt=n.R8UI),X===n.UNSIGNED_SHORT&&(tt=n.R16UI),X===n.UNSIGNED_INT&&(tt=n.R32UI),X===n.BYTE&&(tt=n.R8I),X===n.SHORT&&(tt=n.R16I),X===n.INT&&(tt=n.R32I)),S===n.RG&&(X===n.FLOAT&&(tt=n.RG32F),X===n.HALF_FLOAT&&(tt=n.RG16F),X===n.UNSIGNED_BYTE&&(tt=n.RG8),X===n.UNSIGNED_SHORT&&vt&&(tt=vt.RG16_EXT),X===n.SHORT&&vt&&(tt=vt.RG16_SNORM_EXT)),S===n.RG_INTEGER&&(X===n.UNSIGNED_BYTE&&(tt=n.RG8UI),X===n.UNSIGNED_SHORT&&(tt=n.RG16UI),X===n.UNSIGNED_INT&&(tt=n.RG32UI),X===n.BYTE&&(tt=n.RG8I),X===n.SHORT&&(tt=n.RG16I),X===n.INT&&(tt=n.RG32I)),S===n.RGB_INTEGER&&(X===n.UNSIGNED_BYTE&&(tt=n.RGB8UI),X===n.UNSIGNED_SHORT&&(tt=n.RGB16UI),X===n.UNSIGNED_INT&&(tt=n.RGB32UI),X===n.BYTE&&(tt=n.RGB8I),X===n.SHORT&&(tt=n.RGB16I),X===n.INT&&(tt=n.RGB32I)),S===n.RGBA_INTEGER&&(X===n.UNSIGNED_BYTE&&(tt=n.RGBA8UI),X===n.UNSIGNED_SHORT&&(tt=n.RGBA16UI),X===n.UNSIGNED_INT&&(tt=n.RGBA32UI),X===n.BYTE&&(tt=n.RGBA8I),X===n.SHORT&&(tt=n.RGBA16I),X===n.INT&&(tt=n.RGBA32I)),S===n.RGB&&(X===n.UNSIGNED_SHORT&&vt&&(tt=vt.RGB16_EXT),X===n.SHORT&&vt&&(tt=vt.RGB16_SNORM_EXT),X===n.UNSIGNED_INT_5_9_9_9_REV&&(tt=n.RGB9_E5),X===n.UNSIGNED_INT_10F_11F_11F_REV&&(tt=n.R11F_G11F_B10F)),S===n.RGBA){const it=gt?Ro:me.getTransfer(rt);X===n.FLOAT&&(tt=n.RGBA32F),X===n.HALF_FLOAT&&(tt=n.RGBA16F),X===n.UNSIGNED_BYTE&&(tt=it===Ae?n.SRGB8_ALPHA8:n.RGBA8),X===n.UNSIGNED_SHORT&&vt&&(tt=vt.RGBA16_EXT),X===n.SHORT&&vt&&(tt=vt.RGBA16_SNORM_EXT),X===n.UNSIGNED_SHORT_4_4_4_4&&(tt=n.RGBA4),X===n.UNSIGNED_SHORT_5_5_5_1&&(tt=n.RGB5_A1)}return(tt===n.R16F||tt===n.R32F||tt===n.RG16F||tt===n.RG32F||tt===n.RGBA16F||tt===n.RGBA32F)&&t.get("EXT_color_buffer_float"),tt}function g(C,S){let X;return C?S===null||S===ki||S===Ar?X=n.DEPTH24_STENCIL8:S===Bi?X=n.DEPTH32F_STENCIL8:S===va&&(X=n.DEPTH24_STENCIL8,Kt("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):S===null||S===ki||S===Ar?X=n.DEPTH_COMPONENT24:S===Bi?X=n.DEPTH_COMPONENT32F:S===va&&(X=n.DEPTH_COMPONENT16),X}function T(C,S){return A(C)===!0||C.isFramebufferTexture&&C.minFilter!==wn&&C.minFilter!==zn?Math.log2(Math.max(S.width,S.height))+1:C.mipmaps.length>0?C.mipmaps.length:C.isCompressedTexture&&Array.isArray(C.image)?S.mipmaps.length:1}function z(C){const S=new WeakRef(C);i.get(C).__ref=S,v.add(S),M.register(C,S,S)}function U(C){const S=i.get(C).__ref;S!==void 0&&(v.delete(S),M.unregister(S))}function D(C){B(C.target)}function I(C){L(C.target)}function B(C){C.removeEventListener("dispose",D),U(C),Y(C),C.isVideoTexture&&h.delete(C),C.isHTMLTexture&&d.delete(C)}function L(C){C.removeEventListener("dispose",I),U(C),lt(C)}function G(){for(const C of v){const S=C.deref();S!==void 0&&(S.isRenderTarget===!0?L(S):B(S))}v.clear(),d.clear()}function Y(C){const S=i.get(C);if(S.__webglInit===void 0)return;const X=C.source,ht=m.get(X);if(ht){const rt=ht[S.__cacheKey];rt.usedTimes--,rt.usedTimes===0&&k(C),Object.keys(ht).length===0&&m.delete(X)}i.remove(C)}function k(C){const S=i.get(C);n.deleteTexture(S.__webglTexture);const X=C.source,ht=m.get(X);delete ht[S.__cacheKey],a.memory.textures--}function lt(C){const S=i.get(C);S.__depthDisposeCallback&&S.__depthDisposeCallback();const X=C.depthTexture;if(X&&X.renderTarget===C&&B(X),C.isWebGLCubeRenderTarget)for(let rt=0;rt<6;rt++){if(Array.isArray(S.__webglFramebuffer[rt]))for(let gt=0;gt<S.__webglFramebuffer[rt].length;gt++)n.deleteFramebuffer(S.__webglFramebuffer[rt][gt]);else n.deleteFramebuffer(S.__webglFramebuffer[rt]);S.__webglDepthbuffer&&n.deleteRenderbuffer(S.__webglDepthbuffer[rt])}else{if(Array.isArray(S.__webglFramebuffer))for(let rt=0;rt<S.__webglFramebuffer.length;rt++)n.deleteFramebuffer(S.__webglFramebuffer[rt]);else n.deleteFramebuffer(S.__webglFramebuffer);if(S.__webglDepthbuffer&&n.deleteRenderbuffer(S.__webglDepthbuffer),S.__webglMultisampledFramebuffer&&n.deleteFramebuffer(S.__webglMultisampledFramebuffer),S.__webglColorRenderbuffer)for(let rt=0;rt<S.__webglColorRenderbuffer.length;rt++)S.__webglColorRenderbuffer[rt]&&n.deleteRenderbuffer(S.__webglColorRenderbuffer[rt]);S.__webglDepthRenderbuffer&&n.deleteRenderbuffer(S.__webglDepthRenderbuffer)}const ht=C.textures;for(let rt=0,gt=ht.length;rt<gt;rt++){const vt=i.get(ht[rt]);vt.__webglTexture&&(n.deleteTexture(vt.__webglTexture),a.memory.textures--),i.remove(ht[rt])}i.remove(C)}let K=0;function Q(){K=0}function nt(){return K}function ut(C){K=C}function ot(){const C=K;return C>=s.maxTextures&&Kt("WebGLTextures: Trying to use "+(C+1)+" texture units while this GPU supports only "+s.maxTextures),K+=1,C}function j(C){const S=[];return S.push(C.wrapS),S.push(C.wrapT),S.push(C.wrapR||0),S.push(C.magFilter),S.push(C.minFilter),S.push(C.anisotropy),S.push(C.internalFormat),S.push(C.format),S.push(C.type),S.push(C.generateMipmaps),S.push(C.mipmapsAutoUpdate),S.push(C.premultiplyAlpha),S.push(C.flipY),S.push(C.unpackAlignment),S.push(C.colorSpace),S.join()}function pt(C,S){const X=i.get(C);if(C.isVideoTexture&&De(C),C.isRenderTargetTexture===!1&&C.isExternalTexture!==!0&&C.version>0&&X.__version!==C.version){const ht=C.image;if(ht===null)Kt("WebGLRenderer: Texture marked for update but no image data found.");else if(ht.complete===!1)Kt("WebGLRenderer: Texture marked for update but image is incomplete");else{Ue(X,C,S);return}}else C.isExternalTexture&&(X.__webglTexture=C.sourceTexture?C.sourceTexture:null);e.bindTexture(n.TEXTURE_2D,X.__webglTexture,n.TEXTURE0+S)}function _t(C,S){const X=i.get(C);if(C.isRenderTargetTexture===!1&&C.version>0&&X.__version!==C.version){Ue(X,C,S);return}else C.isExternalTexture&&(X.__webglTexture=C.sourceTexture?C.sourceTexture:null);e.bindTexture(n.TEXTURE_2D_ARRAY,X.__webglTexture,n.TEXTURE0+S)}function Tt(C,S){const X=i.get(C);if(C.isRenderTargetTexture===!1&&C.version>0&&X.__version!==C.version){Ue(X,C,S);return}e.bindTexture(n.TEXTURE_3D,X.__webglTexture,n.TEXTURE0+S)}function Mt(C,S){const X=i.get(C);if(C.version>0&&X.__version!==C.version){je(X,C,S);return}e.bindTexture(n.TEXTURE_CUBE_MAP,X.__webglTexture,n.TEXTURE0+S)}const Gt={[mc]:n.REPEAT,[ji]:n.CLAMP_TO_EDGE,[gc]:n.MIRRORED_REPEAT},ee={[wn]:n.NEAREST,[bg]:n.NEAREST_MIPMAP_NEAREST,[Ia]:n.NEAREST_MIPMAP_LINEAR,[zn]:n.LINEAR,[hl]:n.LINEAR_MIPMAP_NEAREST,[Ss]:n.LINEAR_MIPMAP_LINEAR},kt={[Rg]:n.NEVER,[Xf]:n.ALWAYS,[Cg]:n.LESS,[Vf]:n.LEQUAL,[Pg]:n.EQUAL,[Wf]:n.GEQUAL,[Lg]:n.GREATER,[Dg]:n.NOTEQUAL};function oe(C,S){if(S.type===Bi&&t.has("OES_texture_float_linear")===!1&&(S.magFilter===zn||S.magFilter===hl||S.magFilter===Ia||S.magFilter===Ss||S.minFilter===zn||S.minFilter===hl||S.minFilter===Ia||S.minFilter===Ss)&&Kt("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),n.texParameteri(C,n.TEXTURE_WRAP_S,Gt[S.wrapS]),n.texParameteri(C,n.TEXTURE_WRAP_T,Gt[S.wrapT]),(C===n.TEXTURE_3D||C===n.TEXTURE_2D_ARRAY)&&n.texParameteri(C,n.TEXTURE_WRAP_R,Gt[S.wrapR]),n.texParameteri(C,n.TEXTURE_MAG_FILTER,ee[S.magFilter]),n.texParameteri(C,n.TEXTURE_MIN_FILTER,ee[S.minFilter]),S.compareFunction&&(n.texParameteri(C,n.TEXTURE_COMPARE_MODE,n.COMPARE_REF_TO_TEXTURE),n.texParameteri(C,n.TEXTURE_COMPARE_FUNC,kt[S.compareFunction])),t.has("EXT_texture_filter_anisotropic")===!0){if(S.magFilter===wn||S.minFilter!==Ia&&S.minFilter!==Ss||S.type===Bi&&t.has("OES_texture_float_linear")===!1)return;if(S.anisotropy>1||i.get(S).__currentAnisotropy){const X=t.get("EXT_texture_filter_anisotropic");n.texParameterf(C,X.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(S.anisotropy,s.getMaxAnisotropy())),i.get(S).__currentAnisotropy=S.anisotropy}}}function se(C,S){let X=!1;C.__webglInit===void 0&&(C.__webglInit=!0,S.addEventListener("dispose",D),z(S));const ht=S.source;let rt=m.get(ht);rt===void 0&&(rt={},m.set(ht,rt));const gt=j(S);if(gt!==C.__cacheKey){rt[gt]===void 0&&(rt[gt]={texture:n.createTexture(),usedTimes:0},a.memory.textures++,X=!0),rt[gt].usedTimes++;const vt=rt[C.__cacheKey];vt!==void 0&&(rt[C.__cacheKey].usedTimes--,vt.usedTimes===0&&k(S)),C.__cacheKey=gt,C.__webglTexture=rt[gt].texture}return X}function Qt(C,S,X){return Math.floor(Math.floor(C/X)/S)}function He(C,S,X,ht){const gt=C.updateRanges;if(gt.length===0)e.texSubImage2D(n.TEXTURE_2D,0,0,0,S.width,S.height,X,ht,S.data);else{gt.sort((F,st)=>F.start-st.start);let vt=0;for(let F=1;F<gt.length;F++){const st=gt[vt],et=gt[F],Et=st.start+st.count,mt=Qt(et.start,S.width,4),St=Qt(st.start,S.width,4);et.start<=Et+1&&mt===St&&Qt(et.start+et.count-1,S.width,4)===mt?st.count=Math.max(st.count,et.start+et.count-st.start):(++vt,gt[vt]=et)}gt.length=vt+1;const tt=e.getParameter(n.UNPACK_ROW_LENGTH),it=e.getParameter(n.UNPACK_SKIP_PIXELS),ft=e.getParameter(n.UNPACK_SKIP_ROWS);e.pixelStorei(n.UNPACK_ROW_LENGTH,S.width);for(let F=0,st=gt.length;F<st;F++){const et=gt[F],Et=Math.floor(et.start/4),mt=Math.ceil(et.count/4),St=Et%S.width,Ht=Math.floor(Et/S.width),Yt=mt,ct=1;e.pixelStorei(n.UNPACK_SKIP_PIXELS,St),e.pixelStorei(n.UNPACK_SKIP_ROWS,Ht),e.texSubImage2D(n.TEXTURE_2D,0,St,Ht,Yt,ct,X,ht,S.data)}C.clearUpdateRanges(),e.pixelStorei(n.UNPACK_ROW_LENGTH,tt),e.pixelStorei(n.UNPACK_SKIP_PIXELS,it),e.pixelStorei(n.UNPACK_SKIP_ROWS,ft)}}function Ue(C,S,X){let ht=n.TEXTURE_2D;(S.isDataArrayTexture||S.isCompressedArrayTexture)&&(ht=n.TEXTURE_2D_ARRAY),S.isData3DTexture&&(ht=n.TEXTURE_3D);const rt=se(C,S),gt=S.source;e.bindTexture(ht,C.__webglTexture,n.TEXTURE0+X);const vt=i.get(gt);if(gt.version!==vt.__version||rt===!0){if(e.activeTexture(n.TEXTURE0+X),(typeof ImageBitmap<"u"&&S.image instanceof ImageBitmap)===!1){const ct=me.getPrimaries(me.workingColorSpace),Ft=S.colorSpace===xs?null:me.getPrimaries(S.colorSpace),qt=S.colorSpace===xs||ct===Ft?n.NONE:n.BROWSER_DEFAULT_WEBGL;e.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,S.flipY),e.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),e.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,qt)}e.pixelStorei(n.UNPACK_ALIGNMENT,S.unpackAlignment);let it=x(S.image,!1,s.maxTextureSize);it=zt(S,it);const ft=r.convert(S.format,S.colorSpace),F=r.convert(S.type);let st=E(S.internalFormat,ft,F,S.normalized,S.colorSpace,S.isVideoTexture);oe(ht,S);let et;const Et=S.mipmaps,mt=S.isVideoTexture!==!0,St=vt.__version===void 0||rt===!0,Ht=gt.dataReady,Yt=T(S,it);if(S.isDepthTexture)st=g(S.format===Ms,S.type),St&&(mt?e.texStorage2D(n.TEXTURE_2D,1,st,it.width,it.height):e.texImage2D(n.TEXTURE_2D,0,st,it.width,it.height,0,ft,F,null));else if(S.isDataTexture)if(Et.length>0){mt&&St&&e.texStorage2D(n.TEXTURE_2D,Yt,st,Et[0].width,Et[0].height);for(let ct=0,Ft=Et.length;ct<Ft;ct++)et=Et[ct],mt?Ht&&e.texSubImage2D(n.TEXTURE_2D,ct,0,0,et.width,et.height,ft,F,et.data):e.texImage2D(n.TEXTURE_2D,ct,st,et.width,et.height,0,ft,F,et.data);S.generateMipmaps=!1}else mt?(St&&e.texStorage2D(n.TEXTURE_2D,Yt,st,it.width,it.height),Ht&&He(S,it,ft,F)):e.texImage2D(n.TEXTURE_2D,0,st,it.width,it.height,0,ft,F,it.data);else if(S.isCompressedTexture)if(S.isCompressedArrayTexture){mt&&St&&e.texStorage3D(n.TEXTURE_2D_ARRAY,Yt,st,Et[0].width,Et[0].height,it.depth);for(let ct=0,Ft=Et.length;ct<Ft;ct++)if(et=Et[ct],S.format!==Ei)if(ft!==null)if(mt){if(Ht)if(S.layerUpdates.size>0){const qt=qu(et.width,et.height,S.format,S.type);for(const At of S.layerUpdates){const ie=et.data.subarray(At*qt/et.data.BYTES_PER_ELEMENT,(At+1)*qt/et.data.BYTES_PER_ELEMENT);e.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,ct,0,0,At,et.width,et.height,1,ft,ie)}}else e.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,ct,0,0,0,et.width,et.height,it.depth,ft,et.data)}else e.compressedTexImage3D(n.TEXTURE_2D_ARRAY,ct,st,et.width,et.height,it.depth,0,et.data,0,0);else Kt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else mt?Ht&&e.texSubImage3D(n.TEXTURE_2D_ARRAY,ct,0,0,0,et.width,et.height,it.depth,ft,F,et.data):e.texImage3D(n.TEXTURE_2D_ARRAY,ct,st,et.width,et.height,it.depth,0,ft,F,et.data);S.layerUpdates.size>0&&S.clearLayerUpdates()}else{mt&&St&&e.texStorage2D(n.TEXTURE_2D,Yt,st,Et[0].width,Et[0].height);for(let ct=0,Ft=Et.length;ct<Ft;ct++)et=Et[ct],S.format!==Ei?ft!==null?mt?Ht&&e.compressedTexSubImage2D(n.TEXTURE_2D,ct,0,0,et.width,et.height,ft,et.data):e.compressedTexImage2D(n.TEXTURE_2D,ct,st,et.width,et.height,0,et.data):Kt("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):mt?Ht&&e.texSubImage2D(n.TEXTURE_2D,ct,0,0,et.width,et.height,ft,F,et.data):e.texImage2D(n.TEXTURE_2D,ct,st,et.width,et.height,0,ft,F,et.data)}else if(S.isDataArrayTexture)if(mt){if(St&&e.texStorage3D(n.TEXTURE_2D_ARRAY,Yt,st,it.width,it.height,it.depth),Ht)if(S.layerUpdates.size>0){const ct=qu(it.width,it.height,S.format,S.type);for(const Ft of S.layerUpdates){const qt=it.data.subarray(Ft*ct/it.data.BYTES_PER_ELEMENT,(Ft+1)*ct/it.data.BYTES_PER_ELEMENT);e.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,Ft,it.width,it.height,1,ft,F,qt)}S.clearLayerUpdates()}else e.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,0,it.width,it.height,it.depth,ft,F,it.data)}else e.texImage3D(n.TEXTURE_2D_ARRAY,0,st,it.width,it.height,it.depth,0,ft,F,it.data);else if(S.isData3DTexture)mt?(St&&e.texStorage3D(n.TEXTURE_3D,Yt,st,it.width,it.height,it.depth),Ht&&e.texSubImage3D(n.TEXTURE_3D,0,0,0,0,it.width,it.height,it.depth,ft,F,it.data)):e.texImage3D(n.TEXTURE_3D,0,st,it.width,it.height,it.depth,0,ft,F,it.data);else if(S.isFramebufferTexture){if(St)if(mt)e.texStorage2D(n.TEXTURE_2D,Yt,st,it.width,it.height);else{let ct=it.width,Ft=it.height;for(let qt=0;qt<Yt;qt++)e.texImage2D(n.TEXTURE_2D,qt,st,ct,Ft,0,ft,F,null),ct>>=1,Ft>>=1}}else if(S.isHTMLTexture){if("texElementImage2D"in n){const ct=n.canvas;if(ct.hasAttribute("layoutsubtree")||ct.setAttribute("layoutsubtree","true"),it.parentNode!==ct){ct.appendChild(it),d.add(S),ct.onpaint=Ft=>{const qt=Ft.changedElements;for(const At of d)qt.includes(At.image)&&(At.needsUpdate=!0)},ct.requestPaint();return}if(n.texElementImage2D.length===3)n.texElementImage2D(n.TEXTURE_2D,n.RGBA8,it);else{const qt=n.RGBA,At=n.RGBA,ie=n.UNSIGNED_BYTE;n.texElementImage2D(n.TEXTURE_2D,0,qt,At,ie,it)}n.texParameteri(n.TEXTURE_2D,n.TEXTURE_MIN_FILTER,n.LINEAR),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_S,n.CLAMP_TO_EDGE),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_T,n.CLAMP_TO_EDGE)}}else if(Et.length>0){if(mt&&St){const ct=Wt(Et[0]);e.texStorage2D(n.TEXTURE_2D,Yt,st,ct.width,ct.height)}for(let ct=0,Ft=Et.length;ct<Ft;ct++)et=Et[ct],mt?Ht&&e.texSubImage2D(n.TEXTURE_2D,ct,0,0,ft,F,et):e.texImage2D(n.TEXTURE_2D,ct,st,ft,F,et);S.generateMipmaps=!1}else if(mt){if(St){const ct=Wt(it);e.texStorage2D(n.TEXTURE_2D,Yt,st,ct.width,ct.height)}Ht&&e.texSubImage2D(n.TEXTURE_2D,0,0,0,ft,F,it)}else e.texImage2D(n.TEXTURE_2D,0,st,ft,F,it);A(S)&&S.mipmapsAutoUpdate===!0&&y(ht),vt.__version=gt.version,S.onUpdate&&S.onUpdate(S)}C.__version=S.version}function je(C,S,X){if(S.image.length!==6)return;const ht=se(C,S),rt=S.source;e.bindTexture(n.TEXTURE_CUBE_MAP,C.__webglTexture,n.TEXTURE0+X);const gt=i.get(rt);if(rt.version!==gt.__version||ht===!0){e.activeTexture(n.TEXTURE0+X);const vt=me.getPrimaries(me.workingColorSpace),tt=S.colorSpace===xs?null:me.getPrimaries(S.colorSpace),it=S.colorSpace===xs||vt===tt?n.NONE:n.BROWSER_DEFAULT_WEBGL;e.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,S.flipY),e.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),e.pixelStorei(n.UNPACK_ALIGNMENT,S.unpackAlignment),e.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,it);const ft=S.isCompressedTexture||S.image[0].isCompressedTexture,F=S.image[0]&&S.image[0].isDataTexture,st=[];for(let At=0;At<6;At++)!ft&&!F?st[At]=x(S.image[At],!0,s.maxCubemapSize):st[At]=F?S.image[At].image:S.image[At],st[At]=zt(S,st[At]);const et=st[0],Et=r.convert(S.format,S.colorSpace),mt=r.convert(S.type);let St=E(S.internalFormat,Et,mt,S.normalized,S.colorSpace);const Ht=S.isVideoTexture!==!0,Yt=gt.__version===void 0||ht===!0,ct=rt.dataReady;let Ft=T(S,et);oe(n.TEXTURE_CUBE_MAP,S);let qt;if(S.isDepthTexture){if(St=g(S.format===Ms,S.type),Yt)if(Ht)e.texStorage2D(n.TEXTURE_CUBE_MAP,1,St,et.width,et.height);else for(let At=0;At<6;At++)e.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,0,St,et.width,et.height,0,Et,mt,null)}else if(ft){Ht&&Yt&&e.texStorage2D(n.TEXTURE_CUBE_MAP,Ft,St,et.width,et.height);for(let At=0;At<6;At++){qt=st[At].mipmaps;for(let ie=0;ie<qt.length;ie++){const Fe=qt[ie];S.format!==Ei?Et!==null?Ht?ct&&e.compressedTexSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,ie,0,0,Fe.width,Fe.height,Et,Fe.data):e.compressedTexImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,ie,St,Fe.width,Fe.height,0,Fe.data):Kt("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Ht?ct&&e.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,ie,0,0,Fe.width,Fe.height,Et,mt,Fe.data):e.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,ie,St,Fe.width,Fe.height,0,Et,mt,Fe.data)}}}else{if(qt=S.mipmaps,Ht&&Yt){qt.length>0&&Ft++;const At=Wt(st[0]);e.texStorage2D(n.TEXTURE_CUBE_MAP,Ft,St,At.width,At.height)}for(let At=0;At<6;At++)if(F){Ht?ct&&e.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,0,0,0,st[At].width,st[At].height,Et,mt,st[At].data):e.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,0,St,st[At].width,st[At].height,0,Et,mt,st[At].data);for(let ie=0;ie<qt.length;ie++){const Nn=qt[ie].image[At].image;Ht?ct&&e.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,ie+1,0,0,Nn.width,Nn.height,Et,mt,Nn.data):e.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,ie+1,St,Nn.width,Nn.height,0,Et,mt,Nn.data)}}else{Ht?ct&&e.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,0,0,0,Et,mt,st[At]):e.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,0,St,Et,mt,st[At]);for(let ie=0;ie<qt.length;ie++){const Fe=qt[ie];Ht?ct&&e.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,ie+1,0,0,Et,mt,Fe.image[At]):e.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+At,ie+1,St,Et,mt,Fe.image[At])}}}A(S)&&S.mipmapsAutoUpdate===!0&&y(n.TEXTURE_CUBE_MAP),gt.__version=rt.version,S.onUpdate&&S.onUpdate(S)}C.__version=S.version}function Re(C,S,X,ht,rt,gt){const vt=r.convert(X.format,X.colorSpace),tt=r.convert(X.type),it=E(X.internalFormat,vt,tt,X.normalized,X.colorSpace),ft=i.get(S),F=i.get(X);if(F.__renderTarget=S,!ft.__hasExternalTextures){const st=Math.max(1,S.width>>gt),et=Math.max(1,S.height>>gt);rt===n.TEXTURE_3D||rt===n.TEXTURE_2D_ARRAY?e.texImage3D(rt,gt,it,st,et,S.depth,0,vt,tt,null):e.texImage2D(rt,gt,it,st,et,0,vt,tt,null)}e.bindFramebuffer(n.FRAMEBUFFER,C),yt(S)?o.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,ht,rt,F.__webglTexture,0,ne(S)):(rt===n.TEXTURE_2D||rt>=n.TEXTURE_CUBE_MAP_POSITIVE_X&&rt<=n.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&n.framebufferTexture2D(n.FRAMEBUFFER,ht,rt,F.__webglTexture,gt),e.bindFramebuffer(n.FRAMEBUFFER,null)}function _n(C,S,X){if(n.bindRenderbuffer(n.RENDERBUFFER,C),S.depthBuffer){const ht=S.depthTexture,rt=ht&&ht.isDepthTexture?ht.type:null,gt=g(S.stencilBuffer,rt),vt=S.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;yt(S)?o.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,ne(S),gt,S.width,S.height):X?n.renderbufferStorageMultisample(n.RENDERBUFFER,ne(S),gt,S.width,S.height):n.renderbufferStorage(n.RENDERBUFFER,gt,S.width,S.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,vt,n.RENDERBUFFER,C)}else{const ht=S.textures;for(let rt=0;rt<ht.length;rt++){const gt=ht[rt],vt=r.convert(gt.format,gt.colorSpace),tt=r.convert(gt.type),it=E(gt.internalFormat,vt,tt,gt.normalized,gt.colorSpace);yt(S)?o.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,ne(S),it,S.width,S.height):X?n.renderbufferStorageMultisample(n.RENDERBUFFER,ne(S),it,S.width,S.height):n.renderbufferStorage(n.RENDERBUFFER,it,S.width,S.height)}}n.bindRenderbuffer(n.RENDERBUFFER,null)}function ge(C,S,X){const ht=S.isWebGLCubeRenderTarget===!0;if(e.bindFramebuffer(n.FRAMEBUFFER,C),!(S.depthTexture&&S.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");const rt=i.get(S.depthTexture);rt.__renderTarget=S;const gt=ht?S.depthTexture.image[0]:S.depthTexture.image;(!rt.__webglTexture||gt.width!==S.width||gt.height!==S.height)&&(gt.width=S.width,gt.height=S.height,S.depthTexture.needsUpdate=!0),ht?Mt(S.depthTexture,0):pt(S.depthTexture,0);const vt=rt.__webglTexture,tt=ne(S),it=ht?n.TEXTURE_CUBE_MAP_POSITIVE_X+X:n.TEXTURE_2D,ft=S.depthTexture.format===Ms?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;if(S.depthTexture.format===bs)yt(S)?o.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,ft,it,vt,0,tt):n.framebufferTexture2D(n.FRAMEBUFFER,ft,it,vt,0);else if(S.depthTexture.format===Ms)yt(S)?o.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,ft,it,vt,0,tt):n.framebufferTexture2D(n.FRAMEBUFFER,ft,it,vt,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function cn(C){const S=i.get(C),X=C.isWebGLCubeRenderTarget===!0;if(S.__boundDepthTexture!==C.depthTexture){const ht=C.depthTexture;if(S.__depthDisposeCallback&&S.__depthDisposeCallback(),ht){const rt=()=>{delete S.__boundDepthTexture,delete S.__depthDisposeCallback,ht.removeEventListener("dispose",rt)};ht.addEventListener("dispose",rt),S.__depthDisposeCallback=rt}S.__boundDepthTexture=ht}if(C.depthTexture&&!S.__autoAllocateDepthBuffer)if(X)for(let ht=0;ht<6;ht++)ge(S.__webglFramebuffer[ht],C,ht);else C.texture.mipmaps.length>0?ge(S.__webglFramebuffer[0],C,0):ge(S.__webglFramebuffer,C,0);else if(X){S.__webglDepthbuffer=[];for(let ht=0;ht<6;ht++)if(e.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer[ht]),S.__webglDepthbuffer[ht]===void 0)S.__webglDepthbuffer[ht]=n.createRenderbuffer(),_n(S.__webglDepthbuffer[ht],C,!1);else{const rt=C.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,gt=S.__webglDepthbuffer[ht];n.bindRenderbuffer(n.RENDERBUFFER,gt),n.framebufferRenderbuffer(n.FRAMEBUFFER,rt,n.RENDERBUFFER,gt)}}else if(C.texture.mipmaps.length>0?e.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer[0]):e.bindFramebuffer(n.FRAMEBUFFER,S.__webglFramebuffer),S.__webglDepthbuffer===void 0)S.__webglDepthbuffer=n.createRenderbuffer(),_n(S.__webglDepthbuffer,C,!1);else{const rt=C.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,gt=S.__webglDepthbuffer;n.bindRenderbuffer(n.RENDERBUFFER,gt),n.framebufferRenderbuffer(n.FRAMEBUFFER,rt,n.RENDERBUFFER,gt)}e.bindFramebuffer(n.FRAMEBUFFER,null)}function Xe(C,S,X){const ht=i.get(C);S!==void 0&&Re(ht.__webglFramebuffer,C,C.texture,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,0),X!==void 0&&cn(C)}function tn(C){const S=C.texture,X=i.get(C),ht=i.get(S);C.addEventListener("dispose",I),z(C);const rt=C.textures,gt=C.isWebGLCubeRenderTarget===!0,vt=rt.length>1;if(vt||(ht.__webglTexture===void 0&&(ht.__webglTexture=n.createTexture()),ht.__version=S.version,a.memory.textures++),gt){X.__webglFramebuffer=[];for(let tt=0;tt<6;tt++)if(S.mipmaps.length>0){X.__webglFramebuffer[tt]=[];for(let it=0;it<S.mipmaps.length;it++)X.__webglFramebuffer[tt][it]=n.createFramebuffer()}else X.__webglFramebuffer[tt]=n.createFramebuffer()}else{if(S.mipmaps.length>0){X.__webglFramebuffer=[];for(let tt=0;tt<S.mipmaps.length;tt++)X.__webglFramebuffer[tt]=n.createFramebuffer()}else X.__webglFramebuffer=n.createFramebuffer();if(vt)for(let tt=0,it=rt.length;tt<it;tt++){const ft=i.get(rt[tt]);ft.__webglTexture===void 0&&(ft.__webglTexture=n.createTexture(),a.memory.textures++)}if(C.samples>0&&yt(C)===!1){X.__webglMultisampledFramebuffer=n.createFramebuffer(),X.__webglColorRenderbuffer=[],e.bindFramebuffer(n.FRAMEBUFFER,X.__webglMultisampledFramebuffer);for(let tt=0;tt<rt.length;tt++){const it=rt[tt];X.__webglColorRenderbuffer[tt]=n.createRenderbuffer(),n.bindRenderbuffer(n.RENDERBUFFER,X.__webglColorRenderbuffer[tt]);const ft=r.convert(it.format,it.colorSpace),F=r.convert(it.type),st=E(it.internalFormat,ft,F,it.normalized,it.colorSpace,C.isXRRenderTarget===!0),et=ne(C);n.renderbufferStorageMultisample(n.RENDERBUFFER,et,st,C.width,C.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+tt,n.RENDERBUFFER,X.__webglColorRenderbuffer[tt])}n.bindRenderbuffer(n.RENDERBUFFER,null),C.depthBuffer&&(X.__webglDepthRenderbuffer=n.createRenderbuffer(),_n(X.__webglDepthRenderbuffer,C,!0)),e.bindFramebuffer(n.FRAMEBUFFER,null)}}if(gt){e.bindTexture(n.TEXTURE_CUBE_MAP,ht.__webglTexture),oe(n.TEXTURE_CUBE_MAP,S);for(let tt=0;tt<6;tt++)if(S.mipmaps.length>0)for(let it=0;it<S.mipmaps.length;it++)Re(X.__webglFramebuffer[tt][it],C,S,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+tt,it);else Re(X.__webglFramebuffer[tt],C,S,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+tt,0);A(S)?y(n.TEXTURE_CUBE_MAP):S.mipmaps.length>0&&n.texParameteri(n.TEXTURE_CUBE_MAP,n.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),e.unbindTexture()}else if(vt){for(let tt=0,it=rt.length;tt<it;tt++){const ft=rt[tt],F=i.get(ft);let st=n.TEXTURE_2D;(C.isWebGL3DRenderTarget||C.isWebGLArrayRenderTarget)&&(st=C.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),e.bindTexture(st,F.__webglTexture),oe(st,ft),Re(X.__webglFramebuffer,C,ft,n.COLOR_ATTACHMENT0+tt,st,0),A(ft)&&y(st)}e.unbindTexture()}else{let tt=n.TEXTURE_2D;if((C.isWebGL3DRenderTarget||C.isWebGLArrayRenderTarget)&&(tt=C.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),e.bindTexture(tt,ht.__webglTexture),oe(tt,S),S.mipmaps.length>0)for(let it=0;it<S.mipmaps.length;it++)Re(X.__webglFramebuffer[it],C,S,n.COLOR_ATTACHMENT0,tt,it);else Re(X.__webglFramebuffer,C,S,n.COLOR_ATTACHMENT0,tt,0);A(S)?y(tt):S.mipmaps.length>0&&n.texParameteri(tt,n.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),e.unbindTexture()}C.depthBuffer&&cn(C)}function O(C){const S=C.textures;for(let X=0,ht=S.length;X<ht;X++){const rt=S[X];if(A(rt)&&rt.mipmapsAutoUpdate===!0){const gt=R(C),vt=i.get(rt).__webglTexture;e.bindTexture(gt,vt),y(gt),e.unbindTexture()}}}const Rt=[];function Xt(C){if(C.samples>0){if(yt(C)===!1){const S=C.textures,X=C.width,ht=C.height;let rt=n.COLOR_BUFFER_BIT;const gt=C.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,vt=i.get(C),tt=S.length>1;if(tt)for(let ft=0;ft<S.length;ft++)e.bindFramebuffer(n.FRAMEBUFFER,vt.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+ft,n.RENDERBUFFER,null),e.bindFramebuffer(n.FRAMEBUFFER,vt.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+ft,n.TEXTURE_2D,null,0);e.bindFramebuffer(n.READ_FRAMEBUFFER,vt.__webglMultisampledFramebuffer),C.texture.mipmaps.length>0?e.bindFramebuffer(n.DRAW_FRAMEBUFFER,vt.__webglFramebuffer[0]):e.bindFramebuffer(n.DRAW_FRAMEBUFFER,vt.__webglFramebuffer);for(let ft=0;ft<S.length;ft++){if(C.resolveDepthBuffer&&(C.depthBuffer&&(rt|=n.DEPTH_BUFFER_BIT),C.stencilBuffer&&C.resolveStencilBuffer&&(rt|=n.STENCIL_BUFFER_BIT)),tt){n.framebufferRenderbuffer(n.READ_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.RENDERBUFFER,vt.__webglColorRenderbuffer[ft]);const F=i.get(S[ft]).__webglTexture;n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,F,0)}n.blitFramebuffer(0,0,X,ht,0,0,X,ht,rt,n.NEAREST),c===!0&&(Rt.length=0,Rt.push(n.COLOR_ATTACHMENT0+ft),C.depthBuffer&&C.storeMultisampledDepthBuffer===!1&&Rt.push(gt),n.invalidateFramebuffer(n.READ_FRAMEBUFFER,Rt))}if(e.bindFramebuffer(n.READ_FRAMEBUFFER,null),e.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),tt)for(let ft=0;ft<S.length;ft++){e.bindFramebuffer(n.FRAMEBUFFER,vt.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+ft,n.RENDERBUFFER,vt.__webglColorRenderbuffer[ft]);const F=i.get(S[ft]).__webglTexture;e.bindFramebuffer(n.FRAMEBUFFER,vt.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+ft,n.TEXTURE_2D,F,0)}e.bindFramebuffer(n.DRAW_FRAMEBUFFER,vt.__webglMultisampledFramebuffer)}else if(C.depthBuffer&&C.storeMultisampledDepthBuffer===!1&&c){const S=C.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;n.invalidateFramebuffer(n.DRAW_FRAMEBUFFER,[S])}}}function ne(C){return Math.min(s.maxSamples,C.samples)}function yt(C){const S=i.get(C);return C.samples>0&&t.has("WEBGL_multisampled_render_to_texture")===!0&&S.__useRenderToTexture!==!1}function De(C){const S=a.render.frame;h.get(C)!==S&&(h.set(C,S),C.update())}function zt(C,S){const X=C.colorSpace,ht=C.format,rt=C.type;return C.isCompressedTexture===!0||C.isVideoTexture===!0||X!==Ao&&X!==xs&&(me.getTransfer(X)===Ae?(ht!==Ei||rt!==Jn)&&Kt("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):ve("WebGLTextures: Unsupported texture color space:",X)),S}function Wt(C){return typeof HTMLImageElement<"u"&&C instanceof HTMLImageElement?(l.width=C.naturalWidth||C.width,l.height=C.naturalHeight||C.height):typeof VideoFrame<"u"&&C instanceof VideoFrame?(l.width=C.displayWidth,l.height=C.displayHeight):(l.width=C.width,l.height=C.height),l}this.allocateTextureUnit=ot,this.resetTextureUnits=Q,this.getTextureUnits=nt,this.setTextureUnits=ut,this.setTexture2D=pt,this.setTexture2DArray=_t,this.setTexture3D=Tt,this.setTextureCube=Mt,this.rebindTextures=Xe,this.setupRenderTarget=tn,this.updateRenderTargetMipmap=O,this.updateMultisampleRenderTarget=Xt,this.setupDepthRenderbuffer=cn,this.setupFrameBufferTexture=Re,this.useMultisampledRTT=yt,this.dispose=G}function uM(n,t){function e(i,s=xs){let r;const a=me.getTransfer(s);if(i===Jn)return n.UNSIGNED_BYTE;if(i===mh)return n.UNSIGNED_SHORT_4_4_4_4;if(i===gh)return n.UNSIGNED_SHORT_5_5_5_1;if(i===Bf)return n.UNSIGNED_INT_5_9_9_9_REV;if(i===zf)return n.UNSIGNED_INT_10F_11F_11F_REV;if(i===Ff)return n.BYTE;if(i===Of)return n.SHORT;if(i===va)return n.UNSIGNED_SHORT;if(i===ph)return n.INT;if(i===ki)return n.UNSIGNED_INT;if(i===Bi)return n.FLOAT;if(i===Hi)return n.HALF_FLOAT;if(i===kf)return n.ALPHA;if(i===Hf)return n.RGB;if(i===Ei)return n.RGBA;if(i===bs)return n.DEPTH_COMPONENT;if(i===Ms)return n.DEPTH_STENCIL;if(i===Gf)return n.RED;if(i===_h)return n.RED_INTEGER;if(i===Ws)return n.RG;if(i===vh)return n.RG_INTEGER;if(i===xh)return n.RGBA_INTEGER;if(i===vo||i===xo||i===So||i===Mo)if(a===Ae)if(r=t.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(i===vo)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(i===xo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(i===So)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(i===Mo)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=t.get("WEBGL_compressed_texture_s3tc"),r!==null){if(i===vo)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(i===xo)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(i===So)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(i===Mo)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(i===_c||i===vc||i===xc||i===Sc)if(r=t.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(i===_c)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(i===vc)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(i===xc)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(i===Sc)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(i===Mc||i===yc||i===Ec||i===bc||i===wc||i===wo||i===Tc)if(r=t.get("WEBGL_compressed_texture_etc"),r!==null){if(i===Mc||i===yc)return a===Ae?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(i===Ec)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(i===bc)return r.COMPRESSED_R11_EAC;if(i===wc)return r.COMPRESSED_SIGNED_R11_EAC;if(i===wo)return r.COMPRESSED_RG11_EAC;if(i===Tc)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(i===Ac||i===Rc||i===Cc||i===Pc||i===Lc||i===Dc||i===Nc||i===Ic||i===Uc||i===Fc||i===Oc||i===Bc||i===zc||i===kc)if(r=t.get("WEBGL_compressed_texture_astc"),r!==null){if(i===Ac)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(i===Rc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(i===Cc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(i===Pc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(i===Lc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(i===Dc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(i===Nc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(i===Ic)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(i===Uc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(i===Fc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(i===Oc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(i===Bc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(i===zc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(i===kc)return a===Ae?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(i===Hc||i===Gc||i===Vc)if(r=t.get("EXT_texture_compression_bptc"),r!==null){if(i===Hc)return a===Ae?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(i===Gc)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(i===Vc)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(i===Wc||i===Xc||i===To||i===$c)if(r=t.get("EXT_texture_compression_rgtc"),r!==null){if(i===Wc)return r.COMPRESSED_RED_RGTC1_EXT;if(i===Xc)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(i===To)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(i===$c)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return i===Ar?n.UNSIGNED_INT_24_8:n[i]!==void 0?n[i]:null}return{convert:e}}const dM=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,fM=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`;class pM{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(t,e){if(this.texture===null){const i=new tp(t.texture);(t.depthNear!==e.depthNear||t.depthFar!==e.depthFar)&&(this.depthNear=t.depthNear,this.depthFar=t.depthFar),this.texture=i}}getMesh(t){if(this.texture!==null&&this.mesh===null){const e=t.cameras[0].viewport,i=new As({vertexShader:dM,fragmentShader:fM,uniforms:{depthColor:{value:this.texture},depthWidth:{value:e.z},depthHeight:{value:e.w}}});this.mesh=new bn(new zo(20,20),i)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}}class mM extends Cs{constructor(t,e){super();const i=this;let s=null,r=1,a=null,o="local-floor",c=1,l=null,h=null,d=null,u=null,m=null,v=null;const M=typeof XRWebGLBinding<"u",p=new pM,f={},x=e.getContextAttributes();let A=null,y=null;const R=[],E=[],g=new Jt;let T=null,z=null;const U=new Ln;U.viewport=new Qe;const D=new Ln;D.viewport=new Qe;const I=[U,D],B=new w_;let L=null,G=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(j){let pt=R[j];return pt===void 0&&(pt=new vl,R[j]=pt),pt.getTargetRaySpace()},this.getControllerGrip=function(j){let pt=R[j];return pt===void 0&&(pt=new vl,R[j]=pt),pt.getGripSpace()},this.getHand=function(j){let pt=R[j];return pt===void 0&&(pt=new vl,R[j]=pt),pt.getHandSpace()};function Y(j){const pt=E.indexOf(j.inputSource);if(pt===-1)return;const _t=R[pt];_t!==void 0&&(_t.update(j.inputSource,j.frame,l||a),_t.dispatchEvent({type:j.type,data:j.inputSource}))}function k(){s.removeEventListener("select",Y),s.removeEventListener("selectstart",Y),s.removeEventListener("selectend",Y),s.removeEventListener("squeeze",Y),s.removeEventListener("squeezestart",Y),s.removeEventListener("squeezeend",Y),s.removeEventListener("end",k),s.removeEventListener("inputsourceschange",lt);for(let j=0;j<R.length;j++){const pt=E[j];pt!==null&&(E[j]=null,R[j].disconnect(pt))}L=null,G=null,p.reset();for(const j in f)delete f[j];if(t.setRenderTarget(A),m=null,u=null,d=null,s=null,y=null,ot.stop(),i.isPresenting=!1,t.setPixelRatio(T),t.setSize(g.width,g.height,!1),z!==null){const j=z.camera;j.fov=z.fov,j.zoom=z.zoom,j.updateProjectionMatrix(),z=null}i.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(j){r=j,i.isPresenting===!0&&Kt("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(j){o=j,i.isPresenting===!0&&Kt("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return l||a},this.setReferenceSpace=function(j){l=j},this.getBaseLayer=function(){return u!==null?u:m},this.getBinding=function(){return d===null&&M&&(d=new XRWebGLBinding(s,e)),d},this.getFrame=function(){return v},this.getSession=function(){return s},this.setSession=async function(j){if(s=j,s!==null){if(A=t.getRenderTarget(),s.addEventListener("select",Y),s.addEventListener("selectstart",Y),s.addEventListener("selectend",Y),s.addEventListener("squeeze",Y),s.addEventListener("squeezestart",Y),s.addEventListener("squeezeend",Y),s.addEventListener("end",k),s.addEventListener("inputsourceschange",lt),x.xrCompatible!==!0&&await e.makeXRCompatible(),T=t.getPixelRatio(),t.getSize(g),M&&"createProjectionLayer"in XRWebGLBinding.prototype){let _t=null,Tt=null,Mt=null;x.depth&&(Mt=x.stencil?e.DEPTH24_STENCIL8:e.DEPTH_COMPONENT24,_t=x.stencil?Ms:bs,Tt=x.stencil?Ar:ki);const Gt={colorFormat:e.RGBA8,depthFormat:Mt,scaleFactor:r};d=this.getBinding(),u=d.createProjectionLayer(Gt),s.updateRenderState({layers:[u]}),t.setPixelRatio(1),t.setSize(u.textureWidth,u.textureHeight,!1),y=new hi(u.textureWidth,u.textureHeight,{format:Ei,type:Jn,depthTexture:new Rr(u.textureWidth,u.textureHeight,Tt,void 0,void 0,void 0,void 0,void 0,void 0,_t),stencilBuffer:x.stencil,colorSpace:t.outputColorSpace,samples:x.antialias?4:0,resolveDepthBuffer:u.ignoreDepthValues===!1,resolveStencilBuffer:u.ignoreDepthValues===!1,storeMultisampledDepthBuffer:u.ignoreDepthValues===!1,storeMultisampledStencilBuffer:u.ignoreDepthValues===!1})}else{const _t={antialias:x.antialias,alpha:!0,depth:x.depth,stencil:x.stencil,framebufferScaleFactor:r};m=new XRWebGLLayer(s,e,_t),s.updateRenderState({baseLayer:m}),t.setPixelRatio(1),t.setSize(m.framebufferWidth,m.framebufferHeight,!1),y=new hi(m.framebufferWidth,m.framebufferHeight,{format:Ei,type:Jn,colorSpace:t.outputColorSpace,stencilBuffer:x.stencil,resolveDepthBuffer:m.ignoreDepthValues===!1,resolveStencilBuffer:m.ignoreDepthValues===!1,storeMultisampledDepthBuffer:m.ignoreDepthValues===!1,storeMultisampledStencilBuffer:m.ignoreDepthValues===!1})}y.isXRRenderTarget=!0,this.setFoveation(c),l=null,a=await s.requestReferenceSpace(o),ot.setContext(s),ot.start(),i.isPresenting=!0,i.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return p.getDepthTexture()};function lt(j){for(let pt=0;pt<j.removed.length;pt++){const _t=j.removed[pt],Tt=E.indexOf(_t);Tt>=0&&(E[Tt]=null,R[Tt].disconnect(_t))}for(let pt=0;pt<j.added.length;pt++){const _t=j.added[pt];let Tt=E.indexOf(_t);if(Tt===-1){for(let Gt=0;Gt<R.length;Gt++)if(Gt>=E.length){E.push(_t),Tt=Gt;break}else if(E[Gt]===null){E[Gt]=_t,Tt=Gt;break}if(Tt===-1)break}const Mt=R[Tt];Mt&&Mt.connect(_t)}}function K(j,pt){pt===null?j.matrixWorld.copy(j.matrix):j.matrixWorld.multiplyMatrices(pt.matrixWorld,j.matrix),j.matrixWorldInverse.copy(j.matrixWorld).invert()}this.updateCamera=function(j){if(s===null)return;let pt=j.near,_t=j.far;p.texture!==null&&(p.depthNear>0&&(pt=p.depthNear),p.depthFar>0&&(_t=p.depthFar)),B.near=D.near=U.near=pt,B.far=D.far=U.far=_t,(L!==B.near||G!==B.far)&&(s.updateRenderState({depthNear:B.near,depthFar:B.far}),L=B.near,G=B.far),B.layers.mask=j.layers.mask|6,U.layers.mask=B.layers.mask&-5,D.layers.mask=B.layers.mask&-3;const Tt=j.parent,Mt=B.cameras;K(B,Tt);for(let Gt=0;Gt<Mt.length;Gt++)K(Mt[Gt],Tt);B.projectionMatrix.copy(U.projectionMatrix),B.projectionMatrixInverse.copy(U.projectionMatrixInverse),z===null&&j.isPerspectiveCamera&&(z={camera:j,fov:j.fov,zoom:j.zoom}),Q(j,B,Tt)};function Q(j,pt,_t){_t===null?j.matrix.copy(pt.matrixWorld):(j.matrix.copy(_t.matrixWorld),j.matrix.invert(),j.matrix.multiply(pt.matrixWorld)),j.matrix.decompose(j.position,j.quaternion,j.scale),j.updateMatrixWorld(!0),j.projectionMatrix.copy(pt.projectionMatrix),j.projectionMatrixInverse.copy(pt.projectionMatrixInverse),j.isPerspectiveCamera&&(j.fov=Po*2*Math.atan(1/j.projectionMatrix.elements[5]),j.zoom=1)}this.getCamera=function(){return B},this.getFoveation=function(){if(!(u===null&&m===null))return c},this.setFoveation=function(j){c=j,u!==null&&(u.fixedFoveation=j),m!==null&&m.fixedFoveation!==void 0&&(m.fixedFoveation=j)},this.hasDepthSensing=function(){return p.texture!==null},this.getDepthSensingMesh=function(){return p.getMesh(B)},this.getCameraTexture=function(j){return f[j]};let nt=null;function ut(j,pt){if(h=pt.getViewerPose(l||a),v=pt,h!==null){const _t=h.views;m!==null&&(t.setRenderTargetFramebuffer(y,m.framebuffer),t.setRenderTarget(y));let Tt=!1;_t.length!==B.cameras.length&&(B.cameras.length=0,Tt=!0);for(let kt=0;kt<_t.length;kt++){const oe=_t[kt];let se=null;if(m!==null)se=m.getViewport(oe);else{const He=d.getViewSubImage(u,oe);se=He.viewport,kt===0&&(t.setRenderTargetTextures(y,He.colorTexture,He.depthStencilTexture),t.setRenderTarget(y))}let Qt=I[kt];Qt===void 0&&(Qt=new Ln,Qt.layers.enable(kt),Qt.viewport=new Qe,I[kt]=Qt),Qt.matrix.fromArray(oe.transform.matrix),Qt.matrix.decompose(Qt.position,Qt.quaternion,Qt.scale),Qt.projectionMatrix.fromArray(oe.projectionMatrix),Qt.projectionMatrixInverse.copy(Qt.projectionMatrix).invert(),Qt.viewport.set(se.x,se.y,se.width,se.height),kt===0&&(B.matrix.copy(Qt.matrix),B.matrix.decompose(B.position,B.quaternion,B.scale)),Tt===!0&&B.cameras.push(Qt)}const Mt=s.enabledFeatures;if(Mt&&Mt.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&M){d=i.getBinding();const kt=d.getDepthInformation(_t[0]);kt&&kt.isValid&&kt.texture&&p.init(kt,s.renderState)}if(Mt&&Mt.includes("camera-access")&&M){t.state.unbindTexture(),d=i.getBinding();for(let kt=0;kt<_t.length;kt++){const oe=_t[kt].camera;if(oe){let se=f[oe];se||(se=new tp,f[oe]=se);const Qt=d.getCameraImage(oe);se.sourceTexture=Qt}}}}for(let _t=0;_t<R.length;_t++){const Tt=E[_t],Mt=R[_t];Tt!==null&&Mt!==void 0&&Mt.update(Tt,pt,l||a)}nt&&nt(j,pt),pt.detectedPlanes&&i.dispatchEvent({type:"planesdetected",data:pt}),v=null}const ot=new ap;ot.setAnimationLoop(ut),this.setAnimationLoop=function(j){nt=j},this.dispose=function(){}}}const gM=new Le,gp=new te;gp.set(-1,0,0,0,1,0,0,0,1);function _M(n,t){function e(p,f){p.matrixAutoUpdate===!0&&p.updateMatrix(),f.value.copy(p.matrix)}function i(p,f){f.color.getRGB(p.fogColor.value,ep(n)),f.isFog?(p.fogNear.value=f.near,p.fogFar.value=f.far):f.isFogExp2&&(p.fogDensity.value=f.density)}function s(p,f,x,A,y){f.isNodeMaterial?f.uniformsNeedUpdate=!1:f.isMeshBasicMaterial?r(p,f):f.isMeshLambertMaterial?(r(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshToonMaterial?(r(p,f),d(p,f)):f.isMeshPhongMaterial?(r(p,f),h(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshStandardMaterial?(r(p,f),u(p,f),f.isMeshPhysicalMaterial&&m(p,f,y)):f.isMeshMatcapMaterial?(r(p,f),v(p,f)):f.isMeshDepthMaterial?r(p,f):f.isMeshDistanceMaterial?(r(p,f),M(p,f)):f.isMeshNormalMaterial?r(p,f):f.isLineBasicMaterial?(a(p,f),f.isLineDashedMaterial&&o(p,f)):f.isPointsMaterial?c(p,f,x,A):f.isSpriteMaterial?l(p,f):f.isShadowMaterial?(p.color.value.copy(f.color),p.opacity.value=f.opacity):f.isShaderMaterial&&(f.uniformsNeedUpdate=!1)}function r(p,f){p.opacity.value=f.opacity,f.color&&p.diffuse.value.copy(f.color),f.emissive&&p.emissive.value.copy(f.emissive).multiplyScalar(f.emissiveIntensity),f.map&&(p.map.value=f.map,e(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,e(f.alphaMap,p.alphaMapTransform)),f.bumpMap&&(p.bumpMap.value=f.bumpMap,e(f.bumpMap,p.bumpMapTransform),p.bumpScale.value=f.bumpScale,f.side===Vn&&(p.bumpScale.value*=-1)),f.normalMap&&(p.normalMap.value=f.normalMap,e(f.normalMap,p.normalMapTransform),p.normalScale.value.copy(f.normalScale),f.side===Vn&&p.normalScale.value.negate()),f.displacementMap&&(p.displacementMap.value=f.displacementMap,e(f.displacementMap,p.displacementMapTransform),p.displacementScale.value=f.displacementScale,p.displacementBias.value=f.displacementBias),f.emissiveMap&&(p.emissiveMap.value=f.emissiveMap,e(f.emissiveMap,p.emissiveMapTransform)),f.specularMap&&(p.specularMap.value=f.specularMap,e(f.specularMap,p.specularMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest);const x=t.get(f),A=x.envMap,y=x.envMapRotation;A&&(p.envMap.value=A,p.envMapRotation.value.setFromMatrix4(gM.makeRotationFromEuler(y)).transpose(),A.isCubeTexture&&A.isRenderTargetTexture===!1&&p.envMapRotation.value.premultiply(gp),p.reflectivity.value=f.reflectivity,p.ior.value=f.ior,p.refractionRatio.value=f.refractionRatio),f.lightMap&&(p.lightMap.value=f.lightMap,p.lightMapIntensity.value=f.lightMapIntensity,e(f.lightMap,p.lightMapTransform)),f.aoMap&&(p.aoMap.value=f.aoMap,p.aoMapIntensity.value=f.aoMapIntensity,e(f.aoMap,p.aoMapTransform))}function a(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,f.map&&(p.map.value=f.map,e(f.map,p.mapTransform))}function o(p,f){p.dashSize.value=f.dashSize,p.totalSize.value=f.dashSize+f.gapSize,p.scale.value=f.scale}function c(p,f,x,A){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.size.value=f.size*x,p.scale.value=A*.5,f.map&&(p.map.value=f.map,e(f.map,p.uvTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,e(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function l(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.rotation.value=f.rotation,f.map&&(p.map.value=f.map,e(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,e(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function h(p,f){p.specular.value.copy(f.specular),p.shininess.value=Math.max(f.shininess,1e-4)}function d(p,f){f.gradientMap&&(p.gradientMap.value=f.gradientMap)}function u(p,f){p.metalness.value=f.metalness,f.metalnessMap&&(p.metalnessMap.value=f.metalnessMap,e(f.metalnessMap,p.metalnessMapTransform)),p.roughness.value=f.roughness,f.roughnessMap&&(p.roughnessMap.value=f.roughnessMap,e(f.roughnessMap,p.roughnessMapTransform)),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)}function m(p,f,x){p.ior.value=f.ior,f.diffuseRoughness>0&&(p.diffuseRoughness.value=f.diffuseRoughness,f.diffuseRoughnessMap&&(p.diffuseRoughnessMap.value=f.diffuseRoughnessMap,e(f.diffuseRoughnessMap,p.diffuseRoughnessMapTransform))),f.sheen>0&&(p.sheenColor.value.copy(f.sheenColor).multiplyScalar(f.sheen),p.sheenRoughness.value=f.sheenRoughness,f.sheenColorMap&&(p.sheenColorMap.value=f.sheenColorMap,e(f.sheenColorMap,p.sheenColorMapTransform)),f.sheenRoughnessMap&&(p.sheenRoughnessMap.value=f.sheenRoughnessMap,e(f.sheenRoughnessMap,p.sheenRoughnessMapTransform))),f.clearcoat>0&&(p.clearcoat.value=f.clearcoat,p.clearcoatRoughness.value=f.clearcoatRoughness,f.clearcoatMap&&(p.clearcoatMap.value=f.clearcoatMap,e(f.clearcoatMap,p.clearcoatMapTransform)),f.clearcoatRoughnessMap&&(p.clearcoatRoughnessMap.value=f.clearcoatRoughnessMap,e(f.clearcoatRoughnessMap,p.clearcoatRoughnessMapTransform)),f.clearcoatNormalMap&&(p.clearcoatNormalMap.value=f.clearcoatNormalMap,e(f.clearcoatNormalMap,p.clearcoatNormalMapTransform),p.clearcoatNormalScale.value.copy(f.clearcoatNormalScale),f.side===Vn&&p.clearcoatNormalScale.value.negate())),f.dispersion>0&&(p.dispersion.value=f.dispersion),f.retroreflectivity>0&&(p.retroreflectivity.value=f.retroreflectivity),f.iridescence>0&&(p.iridescence.value=f.iridescence,p.iridescenceIOR.value=f.iridescenceIOR,p.iridescenceThicknessMinimum.value=f.iridescenceThicknessMinimum,p.iridescenceThicknessMaximum.value=f.iridescenceThicknessMaximum,f.iridescenceMap&&(p.iridescenceMap.value=f.iridescenceMap,e(f.iridescenceMap,p.iridescenceMapTransform)),f.iridescenceThicknessMap&&(p.iridescenceThicknessMap.value=f.iridescenceThicknessMap,e(f.iridescenceThicknessMap,p.iridescenceThicknessMapTransform))),f.transmission>0&&(p.transmission.value=f.transmission,p.transmissionSamplerMap.value=x.texture,p.transmissionSamplerSize.value.set(x.width,x.height),f.transmissionMap&&(p.transmissionMap.value=f.transmissionMap,e(f.transmissionMap,p.transmissionMapTransform)),p.thickness.value=f.thickness,f.thicknessMap&&(p.thicknessMap.value=f.thicknessMap,e(f.thicknessMap,p.thicknessMapTransform)),p.attenuationDistance.value=f.attenuationDistance,p.attenuationColor.value.copy(f.attenuationColor)),f.anisotropy>0&&(p.anisotropyVector.value.set(f.anisotropy*Math.cos(f.anisotropyRotation),f.anisotropy*Math.sin(f.anisotropyRotation)),f.anisotropyMap&&(p.anisotropyMap.value=f.anisotropyMap,e(f.anisotropyMap,p.anisotropyMapTransform))),p.specularIntensity.value=f.specularIntensity,p.specularColor.value.copy(f.specularColor),f.specularColorMap&&(p.specularColorMap.value=f.specularColorMap,e(f.specularColorMap,p.specularColorMapTransform)),f.specularIntensityMap&&(p.specularIntensityMap.value=f.specularIntensityMap,e(f.specularIntensityMap,p.specularIntensityMapTransform))}function v(p,f){f.matcap&&(p.matcap.value=f.matcap)}function M(p,f){const x=t.get(f).light;p.referencePosition.value.setFromMatrixPosition(x.matrixWorld),p.nearDistance.value=x.shadow.camera.near,p.farDistance.value=x.shadow.camera.far}return{refreshFogUniforms:i,refreshMaterialUniforms:s}}function vM(n,t,e,i){let s={},r={};function a(x,A){const y=A.program;i.uniformBlockBinding(x,y,s[x.id])}function o(x,A){let y=s[x.id];y===void 0&&(v(x),y=c(x),s[x.id]=y,x.addEventListener("dispose",p));const R=A.program;i.updateUBOMapping(x,R);const E=t.render.frame;r[x.id]!==E&&(l(x),r[x.id]=E)}function c(x){const A=n.createBuffer(),y=x.__size,R=x.usage;return n.bindBuffer(n.UNIFORM_BUFFER,A),n.bufferData(n.UNIFORM_BUFFER,y,R),n.bindBuffer(n.UNIFORM_BUFFER,null),A}function l(x){const A=s[x.id],y=x.uniforms,R=x.__cache;n.bindBuffer(n.UNIFORM_BUFFER,A);for(let E=0,g=y.length;E<g;E++){const T=y[E];if(Array.isArray(T))for(let z=0,U=T.length;z<U;z++)h(T[z],E,z,R);else h(T,E,0,R)}n.bindBuffer(n.UNIFORM_BUFFER,null)}function h(x,A,y,R){if(u(x,A,y,R)===!0){const E=x.__offset,g=x.value;if(Array.isArray(g)){let T=0;for(let z=0;z<g.length;z++){const U=g[z],D=M(U,!0);d(U,x.__data,T),T+=D.storage/Float32Array.BYTES_PER_ELEMENT}}else d(g,x.__data,0);n.bufferSubData(n.UNIFORM_BUFFER,E,x.__data)}}function d(x,A,y){typeof x=="number"||typeof x=="boolean"?A[y]=x:x.isMatrix3?(A[y]=x.elements[0],A[y+1]=x.elements[1],A[y+2]=x.elements[2],A[y+3]=0,A[y+4]=x.elements[3],A[y+5]=x.elements[4],A[y+6]=x.elements[5],A[y+7]=0,A[y+8]=x.elements[6],A[y+9]=x.elements[7],A[y+10]=x.elements[8],A[y+11]=0):ArrayBuffer.isView(x)?A.set(x.subarray(0,A.length-y),y):x.toArray(A,y)}function u(x,A,y,R){const E=x.value,g=A+"_"+y;if(Array.isArray(E)){R[g]===void 0&&(R[g]=[]);const T=R[g];let z=!1;for(let U=0;U<E.length;U++)m(E[U],T,U)===!0&&(z=!0);return z}return m(E,R,g)}function m(x,A,y){if(A[y]===void 0)return typeof x=="number"||typeof x=="boolean"?A[y]=x:ArrayBuffer.isView(x)?A[y]=x.slice():A[y]=x.clone(),!0;{const R=A[y];if(typeof x=="number"||typeof x=="boolean"){if(R!==x)return A[y]=x,!0}else{if(ArrayBuffer.isView(x))return!0;if(R.equals(x)===!1)return R.copy(x),!0}}return!1}function v(x){const A=x.uniforms;let y=0;const R=16;for(let g=0,T=A.length;g<T;g++){const z=Array.isArray(A[g])?A[g]:[A[g]];for(let U=0,D=z.length;U<D;U++){const I=z[U],B=Array.isArray(I.value)?I.value:[I.value],L=Array.isArray(A[g])||Array.isArray(I.value);let G=y;for(let k=0,lt=B.length;k<lt;k++){const K=B[k],Q=M(K,L),nt=y%R,ut=nt%Q.boundary,ot=nt+ut;y+=ut,ot!==0&&R-ot<Q.storage&&(y+=R-ot),k===0&&(G=y),y+=Q.storage}const Y=I.type==="int"?Int32Array:I.type==="uint"?Uint32Array:Float32Array;I.__data=new Y((y-G)/Float32Array.BYTES_PER_ELEMENT),I.__offset=G}}const E=y%R;return E>0&&(y+=R-E),x.__size=y,x.__cache={},this}function M(x,A){const y={boundary:0,storage:0};return typeof x=="number"||typeof x=="boolean"?(y.boundary=4,y.storage=4):x.isVector2?(y.boundary=8,y.storage=8):x.isVector3||x.isColor?(y.boundary=16,y.storage=12):x.isVector4?(y.boundary=16,y.storage=16):x.isMatrix3?(y.boundary=16,y.storage=48):x.isMatrix4?(y.boundary=16,y.storage=64):x.isTexture?Kt("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(x)?(y.boundary=16,y.storage=x.byteLength):Kt("WebGLRenderer: Unsupported uniform value type.",x),A===!0&&(y.boundary=16,y.storage=Math.ceil(y.storage/16)*16),y}function p(x){const A=x.target;A.removeEventListener("dispose",p),n.deleteBuffer(s[A.id]),delete s[A.id],delete r[A.id]}function f(){for(const x in s)n.deleteBuffer(s[x]);s={},r={}}return{bind:a,update:o,dispose:f}}const xM=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]);let Ii=null;function SM(){return Ii===null&&(Ii=new l_(xM,16,16,Ws,Hi),Ii.name="DFG_LUT",Ii.minFilter=zn,Ii.magFilter=zn,Ii.wrapS=ji,Ii.wrapT=ji,Ii.generateMipmaps=!1,Ii.needsUpdate=!0),Ii}class _p{constructor(t={}){const{canvas:e=Ug(),context:i=null,depth:s=!0,stencil:r=!1,alpha:a=!1,antialias:o=!1,premultipliedAlpha:c=!0,preserveDrawingBuffer:l=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:d=!1,reversedDepthBuffer:u=!1,outputBufferType:m=Jn}=t;this.isWebGLRenderer=!0;let v;if(i!==null){if(typeof WebGLRenderingContext<"u"&&i instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");v=i.getContextAttributes().alpha}else v=a;const M=m,p=new Set([xh,vh,_h]),f=new Set([Jn,ki,va,Ar,mh,gh]),x=new Uint32Array(4),A=new Int32Array(4),y={textures:[],min:[],max:[],resolution:[]};let R=null,E=null;const g=[],T=[];let z=null;this.domElement=e,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=ts,this.toneMappingExposure=1,this.transmissionResolutionScale=1;const U=this;let D=!1,I=null,B=null,L=null,G=null;this._outputColorSpace=ai;let Y=0,k=0,lt=null,K=-1,Q=null;const nt=new Qe,ut=new Qe;let ot=null;const j=new le(0);let pt=0,_t=e.width,Tt=e.height,Mt=1,Gt=null,ee=null;const kt=new Qe(0,0,_t,Tt),oe=new Qe(0,0,_t,Tt);let se=!1;const Qt=new Sa,He=new bh;let Ue=!1,je=!1;const Re=new Le,_n=new V,ge=new Qe,cn={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0};let Xe=!1;function tn(){return lt===null?Mt:1}let O=i;function Rt(w,H){return e.getContext(w,H)}let Xt,ne,yt,De,zt,Wt,C,S,X,ht,rt,gt,vt,tt,it,ft,F,st,et,Et,mt,St,Ht;try{const w={alpha:!0,depth:s,stencil:r,antialias:o,premultipliedAlpha:c,preserveDrawingBuffer:l,powerPreference:h,failIfMajorPerformanceCaveat:d};if("setAttribute"in e&&e.setAttribute("data-engine",`three.js r${fh}`),e.addEventListener("webglcontextlost",Ft,!1),e.addEventListener("webglcontextrestored",qt,!1),e.addEventListener("webglcontextcreationerror",At,!1),O===null){const H="webgl2";if(O=Rt(H,w),O===null)throw Rt(H)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}Yt()}catch(w){throw e.removeEventListener("webglcontextlost",Ft,!1),e.removeEventListener("webglcontextrestored",qt,!1),e.removeEventListener("webglcontextcreationerror",At,!1),ve("WebGLRenderer: "+w.message),w}function Yt(){Xt=new bx(O),Xt.init(),mt=new uM(O,Xt),ne=new fx(O,Xt,t,mt),yt=new cM(O,Xt),ne.reversedDepthBuffer&&u&&yt.buffers.depth.setReversed(!0),B=O.createFramebuffer(),L=O.createFramebuffer(),G=O.createFramebuffer(),De=new Ax(O),zt=new KS,Wt=new hM(O,Xt,yt,zt,ne,mt,De),C=new Ex(U),S=new C_(O),St=new ux(O,S),X=new wx(O,S,De,St),ht=new Cx(O,X,S,St,De),st=new Rx(O,ne,Wt),it=new px(zt),rt=new qS(U,C,Xt,ne,St,it),gt=new _M(U,zt),vt=new JS,tt=new iM(Xt),F=new hx(U,C,yt,ht,v,c),ft=new lM(U,ht,ne),Ht=new vM(O,De,ne,yt),et=new dx(O,Xt,De),Et=new Tx(O,Xt,De),De.programs=rt.programs,U.capabilities=ne,U.extensions=Xt,U.properties=zt,U.renderLists=vt,U.shadowMap=ft,U.state=yt,U.info=De}M!==Jn&&(z=new Lx(M,e.width,e.height,o,s,r));const ct=new mM(U,O);this.xr=ct,this.getContext=function(){return O},this.getContextAttributes=function(){return O.getContextAttributes()},this.forceContextLoss=function(){const w=Xt.get("WEBGL_lose_context");w&&w.loseContext()},this.forceContextRestore=function(){const w=Xt.get("WEBGL_lose_context");w&&w.restoreContext()},this.getPixelRatio=function(){return Mt},this.setPixelRatio=function(w){w!==void 0&&(Mt=w,this.setSize(_t,Tt,!1))},this.getSize=function(w){return w.set(_t,Tt)},this.setSize=function(w,H,J=!0){if(ct.isPresenting){Kt("WebGLRenderer: Can't change size while VR device is presenting.");return}_t=w,Tt=H,e.width=Math.floor(w*Mt),e.height=Math.floor(H*Mt),J===!0&&(e.style.width=w+"px",e.style.height=H+"px"),z!==null&&z.setSize(e.width,e.height),this.setViewport(0,0,w,H)},this.getDrawingBufferSize=function(w){return w.set(_t*Mt,Tt*Mt).floor()},this.setDrawingBufferSize=function(w,H,J){_t=w,Tt=H,Mt=J,e.width=Math.floor(w*J),e.height=Math.floor(H*J),this.setViewport(0,0,w,H)},this.setEffects=function(w){if(M===Jn){ve("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(w){for(let H=0;H<w.length;H++)if(w[H].isOutputPass===!0){Kt("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}z.setEffects(w||[])},this.getCurrentViewport=function(w){return w.copy(nt)},this.getViewport=function(w){return w.copy(kt)},this.setViewport=function(w,H,J,$){w.isVector4?kt.set(w.x,w.y,w.z,w.w):kt.set(w,H,J,$),yt.viewport(nt.copy(kt).multiplyScalar(tn()).round())},this.getScissor=function(w){return w.copy(oe)},this.setScissor=function(w,H,J,$){w.isVector4?oe.set(w.x,w.y,w.z,w.w):oe.set(w,H,J,$),yt.scissor(ut.copy(oe).multiplyScalar(tn()).round())},this.getScissorTest=function(){return se},this.setScissorTest=function(w){yt.setScissorTest(se=w)},this.setOpaqueSort=function(w){Gt=w},this.setTransparentSort=function(w){ee=w},this.getClearColor=function(w){return w.copy(F.getClearColor())},this.setClearColor=function(){F.setClearColor(...arguments)},this.getClearAlpha=function(){return F.getClearAlpha()},this.setClearAlpha=function(){F.setClearAlpha(...arguments)},this.clear=function(w=!0,H=!0,J=!0){let $=0;if(w){let q=!1;if(lt!==null){const bt=lt.texture.format;q=p.has(bt)}if(q){const bt=lt.texture.type,Ct=f.has(bt),wt=F.getClearColor(),Pt=F.getClearAlpha(),Bt=wt.r,Zt=wt.g,ce=wt.b;Ct?(x[0]=Bt,x[1]=Zt,x[2]=ce,x[3]=Pt,O.clearBufferuiv(O.COLOR,0,x)):(A[0]=Bt,A[1]=Zt,A[2]=ce,A[3]=Pt,O.clearBufferiv(O.COLOR,0,A))}else $|=O.COLOR_BUFFER_BIT}H&&($|=O.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),J&&($|=O.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),$!==0&&O.clear($)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(w){w.setRenderer(this),I=w},this.dispose=function(){e.removeEventListener("webglcontextlost",Ft,!1),e.removeEventListener("webglcontextrestored",qt,!1),e.removeEventListener("webglcontextcreationerror",At,!1),F.dispose(),vt.dispose(),tt.dispose(),Wt.dispose(),zt.dispose(),C.dispose(),ht.dispose(),X.dispose(),St.dispose(),Ht.dispose(),rt.dispose(),ct.dispose(),ct.removeEventListener("sessionstart",Ca),ct.removeEventListener("sessionend",wi),Gi.stop()};function Ft(w){w.preventDefault(),_u("WebGLRenderer: Context Lost."),D=!0}function qt(){_u("WebGLRenderer: Context Restored."),D=!1;const w=De.autoReset,H=ft.enabled,J=ft.autoUpdate,$=ft.needsUpdate,q=ft.type;Yt(),De.autoReset=w,ft.enabled=H,ft.autoUpdate=J,ft.needsUpdate=$,ft.type=q}function At(w){ve("WebGLRenderer: A WebGL context could not be created. Reason: ",w.statusMessage)}function ie(w){const H=w.target;H.removeEventListener("dispose",ie),Fe(H)}function Fe(w){Nn(w),zt.remove(w)}function Nn(w){const H=zt.get(w).programs;H!==void 0&&(H.forEach(function(J){rt.releaseProgram(J)}),w.isShaderMaterial&&rt.releaseShaderCache(w))}this.renderBufferDirect=function(w,H,J,$,q,bt){H===null&&(H=cn);const Ct=q.isMesh&&q.matrixWorld.determinantAffine()<0,wt=Gr(w,H,J,$,q);yt.setMaterial($,Ct);let Pt=J.index,Bt=1;if($.wireframe===!0){if(Pt=X.getWireframeAttribute(J),Pt===void 0)return;Bt=2}const Zt=J.drawRange,ce=J.attributes.position;let Ot=Zt.start*Bt,he=(Zt.start+Zt.count)*Bt;bt!==null&&(Ot=Math.max(Ot,bt.start*Bt),he=Math.min(he,(bt.start+bt.count)*Bt)),Pt!==null?(Ot=Math.max(Ot,0),he=Math.min(he,Pt.count)):ce!=null&&(Ot=Math.max(Ot,0),he=Math.min(he,ce.count));const Ve=he-Ot;if(Ve<0||Ve===1/0)return;St.setup(q,$,wt,J,Pt);let be,we=et;if(Pt!==null&&(be=S.get(Pt),we=Et,we.setIndex(be)),q.isMesh)$.wireframe===!0?(yt.setLineWidth($.wireframeLinewidth*tn()),we.setMode(O.LINES)):we.setMode(O.TRIANGLES);else if(q.isLine){let hn=$.linewidth;hn===void 0&&(hn=1),yt.setLineWidth(hn*tn()),q.isLineSegments?we.setMode(O.LINES):q.isLineLoop?we.setMode(O.LINE_LOOP):we.setMode(O.LINE_STRIP)}else q.isPoints?we.setMode(O.POINTS):q.isSprite&&we.setMode(O.TRIANGLES);if(q.isBatchedMesh)if(Xt.get("WEBGL_multi_draw"))we.renderMultiDraw(q._multiDrawStarts,q._multiDrawCounts,q._multiDrawCount);else{const hn=q._multiDrawStarts,It=q._multiDrawCounts,en=q._multiDrawCount,fe=Pt?S.get(Pt).bytesPerElement:1,Wi=zt.get($).currentProgram.getUniforms();for(let nn=0;nn<en;nn++)Wi.setValue(O,"_gl_DrawID",nn),we.render(hn[nn]/fe,It[nn])}else if(q.isInstancedMesh)we.renderInstances(Ot,Ve,q.count);else if(J.isInstancedBufferGeometry){const hn=J._maxInstanceCount!==void 0?J._maxInstanceCount:1/0,It=Math.min(J.instanceCount,hn);we.renderInstances(Ot,Ve,It)}else we.render(Ot,Ve)};function zr(w,H,J,$){I!==null&&w.isNodeMaterial&&I.setObject($,w),Ue===!0&&it.setState(w,J,!1),w.transparent===!0&&w.side===ci&&w.forceSinglePass===!1?(w.side=Vn,w.needsUpdate=!0,Ti(w,H,$),w.side=Es,w.needsUpdate=!0,Ti(w,H,$),w.side=ci):Ti(w,H,$)}this.compile=function(w,H,J=null){J===null&&(J=w),I!==null&&I.renderStart(w,H,J),E=tt.get(J),E.init(H),T.push(E),J.traverseVisible(function(q){q.isLight&&q.layers.test(H.layers)&&(E.pushLight(q),q.castShadow&&E.pushShadow(q))}),w!==J&&w.traverseVisible(function(q){q.isLight&&q.layers.test(H.layers)&&(E.pushLight(q),q.castShadow&&E.pushShadow(q))}),E.setupLights(),I!==null&&I.updateLights(E.state.lightsArray),je=this.localClippingEnabled,Ue=it.init(this.clippingPlanes,je),Ue===!0&&it.setGlobalState(this.clippingPlanes,H),I!==null&&ft.render(E.state.shadowsArray,J,H);const $=new Set;return w.traverse(function(q){if(!(q.isMesh||q.isPoints||q.isLine||q.isSprite))return;const bt=q.material;if(bt)if(Array.isArray(bt))for(let Ct=0;Ct<bt.length;Ct++){const wt=bt[Ct];zr(wt,J,H,q),$.add(wt)}else zr(bt,J,H,q),$.add(bt)}),E=T.pop(),I!==null&&I.renderEnd(),$},this.compileAsync=function(w,H,J=null){const $=this.compile(w,H,J);return new Promise(q=>{function bt(){if($.forEach(function(Ct){const Pt=zt.get(Ct).currentProgram;(Pt===void 0||Pt.isReady())&&$.delete(Ct)}),$.size===0){q(w);return}setTimeout(bt,10)}Xt.get("KHR_parallel_shader_compile")!==null?bt():setTimeout(bt,10)})};let qs=null;function Zo(w){qs&&qs(w)}function Ca(){Gi.stop()}function wi(){Gi.start()}const Gi=new ap;Gi.setAnimationLoop(Zo),typeof self<"u"&&Gi.setContext(self),this.setAnimationLoop=function(w){qs=w,ct.setAnimationLoop(w),w===null?Gi.stop():Gi.start()},ct.addEventListener("sessionstart",Ca),ct.addEventListener("sessionend",wi),this.render=function(w,H){if(H!==void 0&&H.isCamera!==!0){ve("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(D===!0)return;I!==null&&I.renderStart(w,H);const J=ct.enabled===!0&&ct.isPresenting===!0,$=z!==null&&(lt===null||J)&&z.begin(U,lt);if(w.matrixWorldAutoUpdate===!0&&w.updateMatrixWorld(),H.parent===null&&H.matrixWorldAutoUpdate===!0&&H.updateMatrixWorld(),ct.enabled===!0&&ct.isPresenting===!0&&(z===null||z.isCompositing()===!1)&&(ct.cameraAutoUpdate===!0&&ct.updateCamera(H),H=ct.getCamera()),w.isScene===!0&&w.onBeforeRender(U,w,H,lt),E=tt.get(w,T.length),E.init(H),E.state.textureUnits=Wt.getTextureUnits(),T.push(E),Re.multiplyMatrices(H.projectionMatrix,H.matrixWorldInverse),H.isArrayCamera?He.setFromArrayCamera(H):Qt.setFromProjectionMatrix(Re,bi,H.reversedDepth),je=this.localClippingEnabled,Ue=it.init(this.clippingPlanes,je),R=vt.get(w,g.length),R.init(),g.push(R),this.info.render.frame++,ct.enabled===!0&&ct.isPresenting===!0){const Ct=U.xr.getDepthSensingMesh();Ct!==null&&Vi(Ct,H,-1/0,U.sortObjects)}Vi(w,H,0,U.sortObjects),R.finish(),I!==null&&I.updateLights(E.state.lightsArray),U.sortObjects===!0&&R.sort(Gt,ee),Xe=ct.enabled===!1||ct.isPresenting===!1||ct.hasDepthSensing()===!1,Xe&&F.addToRenderList(R,w),this.info.autoReset===!0&&this.info.reset(),Ue===!0&&it.beginShadows();const q=E.state.shadowsArray;if(ft.render(q,w,H),Ue===!0&&it.endShadows(),($&&z.hasRenderPass())===!1){const Ct=R.opaque,wt=R.transmissive;if(E.setupLights(),H.isArrayCamera){const Pt=H.cameras;if(wt.length>0)for(let Bt=0,Zt=Pt.length;Bt<Zt;Bt++){const ce=Pt[Bt];ui(Ct,wt,w,ce)}Xe&&F.render(w);for(let Bt=0,Zt=Pt.length;Bt<Zt;Bt++){const ce=Pt[Bt];kr(R,w,ce,ce.viewport)}}else wt.length>0&&ui(Ct,wt,w,H),Xe&&F.render(w),kr(R,w,H)}lt!==null&&k===0&&(Wt.updateMultisampleRenderTarget(lt),Wt.updateRenderTargetMipmap(lt)),$&&z.end(U),w.isScene===!0&&w.onAfterRender(U,w,H),St.resetDefaultState(),K=-1,Q=null,T.pop(),T.length>0?(E=T[T.length-1],Wt.setTextureUnits(E.state.textureUnits),Ue===!0&&it.setGlobalState(U.clippingPlanes,E.state.camera)):E=null,g.pop(),g.length>0?R=g[g.length-1]:R=null,I!==null&&I.renderEnd()};function Vi(w,H,J,$){if(w.visible===!1)return;if(w.layers.test(H.layers)){if(w.isGroup)J=w.renderOrder;else if(w.isLOD)w.autoUpdate===!0&&w.update(H);else if(w.isLight)E.pushLight(w),w.castShadow&&E.pushShadow(w);else if(w.isSprite){const Ct=H.isArrayCamera?He:Qt;if(!w.frustumCulled||w.intersectsFrustum(Ct)){$&&ge.setFromMatrixPosition(w.matrixWorld).applyMatrix4(Re);const wt=ht.update(w),Pt=w.material;Pt.visible&&R.push(w,wt,Pt,J,ge.z,null,H)}}else if(w.isMesh||w.isLine||w.isPoints){const Ct=H.isArrayCamera?He:Qt;if(!w.frustumCulled||w.intersectsFrustum(Ct)){const wt=ht.update(w),Pt=w.material;if($&&(w.boundingSphere!==void 0?(w.boundingSphere===null&&w.computeBoundingSphere(),ge.copy(w.boundingSphere.center)):(wt.boundingSphere===null&&wt.computeBoundingSphere(),ge.copy(wt.boundingSphere.center)),ge.applyMatrix4(w.matrixWorld).applyMatrix4(Re)),Array.isArray(Pt)){const Bt=wt.groups;for(let Zt=0,ce=Bt.length;Zt<ce;Zt++){const Ot=Bt[Zt],he=Pt[Ot.materialIndex];he&&he.visible&&R.push(w,wt,he,J,ge.z,Ot,H)}}else Pt.visible&&R.push(w,wt,Pt,J,ge.z,null,H)}}}const bt=w.children;for(let Ct=0,wt=bt.length;Ct<wt;Ct++)Vi(bt[Ct],H,J,$)}function kr(w,H,J,$){const{opaque:q,transmissive:bt,transparent:Ct}=w;E.setupLightsView(J),Ue===!0&&it.setGlobalState(U.clippingPlanes,J),$&&yt.viewport(nt.copy($)),q.length>0&&$e(q,H,J),bt.length>0&&$e(bt,H,J),Ct.length>0&&$e(Ct,H,J),yt.buffers.depth.setTest(!0),yt.buffers.depth.setMask(!0),yt.buffers.color.setMask(!0),yt.setPolygonOffset(!1)}function ui(w,H,J,$){if((J.isScene===!0?J.overrideMaterial:null)!==null)return;if(E.state.transmissionRenderTarget[$.id]===void 0){const Ot=Xt.has("EXT_color_buffer_half_float")||Xt.has("EXT_color_buffer_float");E.state.transmissionRenderTarget[$.id]=new hi(1,1,{generateMipmaps:!0,type:Ot?Hi:Jn,minFilter:Ss,samples:Math.max(4,ne.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:me.workingColorSpace})}const bt=E.state.transmissionRenderTarget[$.id],Ct=$.viewport||nt;bt.setSize(Ct.z*U.transmissionResolutionScale,Ct.w*U.transmissionResolutionScale);const wt=U.getRenderTarget(),Pt=U.getActiveCubeFace(),Bt=U.getActiveMipmapLevel();U.setRenderTarget(bt),U.getClearColor(j),pt=U.getClearAlpha(),pt<1&&U.setClearColor(16777215,.5),U.clear(),Xe&&F.render(J);const Zt=U.toneMapping;U.toneMapping=ts;const ce=$.viewport;if($.viewport!==void 0&&($.viewport=void 0),E.setupLightsView($),Ue===!0&&it.setGlobalState(U.clippingPlanes,$),$e(w,J,$),Wt.updateMultisampleRenderTarget(bt),Wt.updateRenderTargetMipmap(bt),Xt.has("WEBGL_multisampled_render_to_texture")===!1){let Ot=!1;for(let he=0,Ve=H.length;he<Ve;he++){const be=H[he],{object:we,geometry:hn,material:It,group:en}=be;if(It.side===ci&&we.layers.test($.layers)){const fe=It.side;It.side=Vn,It.needsUpdate=!0,Ze(we,J,$,hn,It,en),It.side=fe,It.needsUpdate=!0,Ot=!0}}Ot===!0&&(Wt.updateMultisampleRenderTarget(bt),Wt.updateRenderTargetMipmap(bt))}U.setRenderTarget(wt,Pt,Bt),U.setClearColor(j,pt),ce!==void 0&&($.viewport=ce),U.toneMapping=Zt}function $e(w,H,J){const $=H.isScene===!0?H.overrideMaterial:null;for(let q=0,bt=w.length;q<bt;q++){const Ct=w[q],{object:wt,geometry:Pt,group:Bt}=Ct;let Zt=Ct.material;Zt.allowOverride===!0&&$!==null&&(Zt=$),wt.layers.test(J.layers)&&Ze(wt,H,J,Pt,Zt,Bt)}}function Ze(w,H,J,$,q,bt){I!==null&&q.isNodeMaterial&&I.setObject(w,q),w.onBeforeRender(U,H,J,$,q,bt),w.modelViewMatrix.multiplyMatrices(J.matrixWorldInverse,w.matrixWorld),w.normalMatrix.getNormalMatrix(w.modelViewMatrix),q.onBeforeRender(U,H,J,$,w,bt),q.transparent===!0&&q.side===ci&&q.forceSinglePass===!1?(q.side=Vn,q.needsUpdate=!0,U.renderBufferDirect(J,H,$,q,w,bt),q.side=Es,q.needsUpdate=!0,U.renderBufferDirect(J,H,$,q,w,bt),q.side=ci):U.renderBufferDirect(J,H,$,q,w,bt),w.onAfterRender(U,H,J,$,q,bt)}function Je(w){let H=0;for(const J of w)J.texture!==null&&H++;return H}function Ti(w,H,J){H.isScene!==!0&&(H=cn);const $=zt.get(w),q=E.state.lights,bt=E.state.shadowsArray,Ct=q.state.version,wt=rt.getParameters(w,q.state,bt,H,J,E.state.lightProbeGridArray),Pt=rt.getProgramCacheKey(wt);let Bt=$.programs;$.environment=w.isMeshStandardMaterial||w.isMeshLambertMaterial||w.isMeshPhongMaterial?H.environment:null,$.fog=H.fog;const Zt=w.isMeshStandardMaterial||w.isMeshLambertMaterial&&!w.envMap||w.isMeshPhongMaterial&&!w.envMap;$.envMap=C.get(w.envMap||$.environment,Zt),$.envMapRotation=$.environment!==null&&w.envMap===null?H.environmentRotation:w.envMapRotation,Bt===void 0&&(w.addEventListener("dispose",ie),Bt=new Map,$.programs=Bt,$.programVariants=new Map);let ce=Bt.get(Pt);if(ce!==void 0){if($.currentProgram===ce&&$.lightsStateVersion===Ct)return Hr(w,wt),ce}else wt.uniforms=rt.getUniforms(w),I!==null&&w.isNodeMaterial&&I.build(w,J,wt),w.onBeforeCompile(wt,U),ce=rt.acquireProgram(wt,Pt),Bt.set(Pt,ce),$.uniforms=wt.uniforms;const Ot=$.uniforms;return(!w.isShaderMaterial&&!w.isRawShaderMaterial||w.clipping===!0)&&(Ot.clippingPlanes=it.uniform),Hr(w,wt),$.needsLights=os(w),$.lightsStateVersion=Ct,$.needsLights&&(Ot.ambientLightColor.value=q.state.ambient,Ot.lightProbe.value=q.state.probe,Ot.sunLights.value=q.state.sun,Ot.sunLightShadows.value=q.state.sunShadow,Ot.directionalLights.value=q.state.directional,Ot.directionalLightShadows.value=q.state.directionalShadow,Ot.spotLights.value=q.state.spot,Ot.spotLightShadows.value=q.state.spotShadow,Ot.rectAreaLights.value=q.state.rectArea,Ot.ltc_1.value=q.state.rectAreaLTC1,Ot.ltc_2.value=q.state.rectAreaLTC2,Ot.pointLights.value=q.state.point,Ot.pointLightShadows.value=q.state.pointShadow,Ot.hemisphereLights.value=q.state.hemi,Ot.sunShadowMatrix.value=q.state.sunShadowMatrix,Ot.sunShadowCascade.value=q.state.sunShadowCascade,Ot.directionalShadowMatrix.value=q.state.directionalShadowMatrix,Ot.spotLightMatrix.value=q.state.spotLightMatrix,Ot.spotLightMap.value=q.state.spotLightMap,Ot.pointShadowMatrix.value=q.state.pointShadowMatrix),$.numLightProbeGrids=Je(E.state.lightProbeGridArray),$.currentProgram=ce,$.uniformsList=null,ce}function Wn(w,H,J,$,q){const bt=zt.get(w),Ct=bt.currentProgram.id+","+$+","+q;let wt=bt.programVariants.get(Ct);return wt===void 0?(wt=Ti(w,H,J),bt.programVariants.set(Ct,wt)):(bt.currentProgram=wt,bt.uniformsList=null,bt.outputColorSpace=$,bt.toneMapping=q),wt}function as(w){if(w.uniformsList===null){const H=w.currentProgram.getUniforms();w.uniformsList=Eo.seqWithValue(H.seq,w.uniforms)}return w.uniformsList}function Hr(w,H){const J=zt.get(w);J.outputColorSpace=H.outputColorSpace,J.batching=H.batching,J.batchingColor=H.batchingColor,J.instancing=H.instancing,J.instancingColor=H.instancingColor,J.instancingMorph=H.instancingMorph,J.skinning=H.skinning,J.morphTargets=H.morphTargets,J.morphNormals=H.morphNormals,J.morphColors=H.morphColors,J.morphTargetsCount=H.morphTargetsCount,J.numClippingPlanes=H.numClippingPlanes,J.numIntersection=H.numClipIntersection,J.vertexAlphas=H.vertexAlphas,J.vertexTangents=H.vertexTangents,J.toneMapping=H.toneMapping}function Gr(w,H,J,$,q){H.isScene!==!0&&(H=cn),Wt.resetTextureUnits();const bt=H.fog,Ct=$.isMeshStandardMaterial||$.isMeshLambertMaterial||$.isMeshPhongMaterial?H.environment:null,wt=lt===null?U.outputColorSpace:lt.isXRRenderTarget===!0?lt.texture.colorSpace:me.workingColorSpace,Pt=$.isMeshStandardMaterial||$.isMeshLambertMaterial&&!$.envMap||$.isMeshPhongMaterial&&!$.envMap,Bt=C.get($.envMap||Ct,Pt),Zt=$.vertexColors===!0&&!!J.attributes.color&&J.attributes.color.itemSize===4,ce=!!J.attributes.tangent&&(!!$.normalMap||$.anisotropy>0),Ot=!!J.morphAttributes.position,he=!!J.morphAttributes.normal,Ve=!!J.morphAttributes.color;let be=ts;$.toneMapped&&(lt===null||lt.isXRRenderTarget===!0)&&(be=U.toneMapping);const we=J.morphAttributes.position||J.morphAttributes.normal||J.morphAttributes.color,hn=we!==void 0?we.length:0,It=zt.get($),en=E.state.lights;if(Ue===!0&&(je===!0||w!==Q)){const Te=w===Q&&$.id===K;it.setState($,w,Te)}let fe=!1,Wi=!1;$.version===It.__version?It.needsLights&&It.lightsStateVersion!==en.state.version||q.isBatchedMesh&&It.batching===!1||!q.isBatchedMesh&&It.batching===!0||q.isBatchedMesh&&It.batchingColor===!0&&q._colorsTexture===null||q.isBatchedMesh&&It.batchingColor===!1&&q._colorsTexture!==null||q.isInstancedMesh&&It.instancing===!1||!q.isInstancedMesh&&It.instancing===!0||q.isSkinnedMesh&&It.skinning===!1||!q.isSkinnedMesh&&It.skinning===!0||q.isInstancedMesh&&It.instancingColor===!0&&q.instanceColor===null||q.isInstancedMesh&&It.instancingColor===!1&&q.instanceColor!==null||q.isInstancedMesh&&It.instancingMorph===!0&&q.morphTexture===null||q.isInstancedMesh&&It.instancingMorph===!1&&q.morphTexture!==null||It.envMap!==Bt||$.fog===!0&&It.fog!==bt||It.numClippingPlanes!==void 0&&(It.numClippingPlanes!==it.numPlanes||It.numIntersection!==it.numIntersection)||It.vertexAlphas!==Zt||It.vertexTangents!==ce||It.morphTargets!==Ot||It.morphNormals!==he||It.morphColors!==Ve||It.morphTargetsCount!==hn||It.numLightProbeGrids!==Je(E.state.lightProbeGridArray)?fe=!0:(It.outputColorSpace!==wt||It.toneMapping!==be)&&(Wi=!0):(fe=!0,It.__version=$.version);let nn=It.currentProgram;(fe===!0||Wi===!0)&&(nn=Wi===!0?Wn($,H,q,wt,be):Ti($,H,q),I&&$.isNodeMaterial&&I.onUpdateProgram($,nn,It));let Js=!1,Ai=!1,Xi=!1;const re=nn.getUniforms(),Ye=It.uniforms;if(yt.useProgram(nn.program)&&(Js=!0,Ai=!0,Xi=!0),$.id!==K&&(K=$.id,Ai=!0),Js||Q!==w){yt.buffers.depth.getReversed()&&w.reversedDepth!==!0&&(w._reversedDepth=!0,w.updateProjectionMatrix()),re.setValue(O,"projectionMatrix",w.projectionMatrix),re.setValue(O,"viewMatrix",w.matrixWorldInverse);const sn=re.map.cameraPosition;sn!==void 0&&sn.setValue(O,_n.setFromMatrixPosition(w.matrixWorld)),ne.logarithmicDepthBuffer&&re.setValue(O,"logDepthBufFC",2/(Math.log(w.far+1)/Math.LN2)),($.isMeshPhongMaterial||$.isMeshToonMaterial||$.isMeshLambertMaterial||$.isMeshBasicMaterial||$.isMeshStandardMaterial||$.isShaderMaterial)&&re.setValue(O,"isOrthographic",w.isOrthographicCamera===!0),Q!==w&&(Q=w,Ai=!0,Xi=!0)}if(It.needsLights&&(en.state.sunShadowMap.length>0&&re.setValue(O,"sunShadowMap",en.state.sunShadowMap,Wt),en.state.directionalShadowMap.length>0&&re.setValue(O,"directionalShadowMap",en.state.directionalShadowMap,Wt),en.state.spotShadowMap.length>0&&re.setValue(O,"spotShadowMap",en.state.spotShadowMap,Wt),en.state.pointShadowMap.length>0&&re.setValue(O,"pointShadowMap",en.state.pointShadowMap,Wt)),q.isSkinnedMesh){re.setOptional(O,q,"bindMatrix"),re.setOptional(O,q,"bindMatrixInverse");const Te=q.skeleton;Te&&(Te.boneTexture===null&&Te.computeBoneTexture(),re.setValue(O,"boneTexture",Te.boneTexture,Wt))}q.isBatchedMesh&&(re.setOptional(O,q,"batchingTexture"),re.setValue(O,"batchingTexture",q._matricesTexture,Wt),re.setOptional(O,q,"batchingIdTexture"),re.setValue(O,"batchingIdTexture",q._indirectTexture,Wt),re.setOptional(O,q,"batchingColorTexture"),q._colorsTexture!==null&&re.setValue(O,"batchingColorTexture",q._colorsTexture,Wt));const In=J.morphAttributes;if((In.position!==void 0||In.normal!==void 0||In.color!==void 0)&&st.update(q,J,nn),(Ai||It.receiveShadow!==q.receiveShadow)&&(It.receiveShadow=q.receiveShadow,re.setValue(O,"receiveShadow",q.receiveShadow)),($.isMeshStandardMaterial||$.isMeshLambertMaterial||$.isMeshPhongMaterial)&&$.envMap===null&&H.environment!==null&&(Ye.envMapIntensity.value=H.environmentIntensity),Ye.dfgLUT!==void 0&&(Ye.dfgLUT.value=SM()),Ai){if(re.setValue(O,"toneMappingExposure",U.toneMappingExposure),It.needsLights&&Ks(Ye,Xi),bt&&$.fog===!0&&gt.refreshFogUniforms(Ye,bt),gt.refreshMaterialUniforms(Ye,$,Mt,Tt,E.state.transmissionRenderTarget[w.id]),It.needsLights&&It.numLightProbeGrids>0){const Te=y;let sn=0;for(const Rn of E.state.lightProbeGridArray)Rn.texture!==null&&(Te.textures[sn]=Rn.texture,Te.min[sn]=Rn.boundingBox.min,Te.max[sn]=Rn.boundingBox.max,Te.resolution[sn]=Rn.resolution,sn++);for(const Rn in Te)Te[Rn].length=sn;Ye.probesSH.value=Te.textures,Ye.probesMin.value=Te.min,Ye.probesMax.value=Te.max,Ye.probesResolution.value=Te.resolution}Eo.upload(O,as(It),Ye,Wt)}if($.isShaderMaterial&&$.uniformsNeedUpdate===!0&&(Eo.upload(O,as(It),Ye,Wt),$.uniformsNeedUpdate=!1),$.isSpriteMaterial&&re.setValue(O,"center",q.center),re.setValue(O,"modelViewMatrix",q.modelViewMatrix),re.setValue(O,"normalMatrix",q.normalMatrix),re.setValue(O,"modelMatrix",q.matrixWorld),$.uniformsGroups!==void 0){const Te=$.uniformsGroups;for(let sn=0,Rn=Te.length;sn<Rn;sn++){const Pa=Te[sn];Ht.update(Pa,nn),Ht.bind(Pa,nn)}}return nn}function Ks(w,H){w.ambientLightColor.needsUpdate=H,w.lightProbe.needsUpdate=H,w.sunLights.needsUpdate=H,w.sunLightShadows.needsUpdate=H,w.directionalLights.needsUpdate=H,w.directionalLightShadows.needsUpdate=H,w.pointLights.needsUpdate=H,w.pointLightShadows.needsUpdate=H,w.spotLights.needsUpdate=H,w.spotLightShadows.needsUpdate=H,w.rectAreaLights.needsUpdate=H,w.hemisphereLights.needsUpdate=H}function os(w){return w.isMeshLambertMaterial||w.isMeshToonMaterial||w.isMeshPhongMaterial||w.isMeshStandardMaterial||w.isShadowMaterial||w.isShaderMaterial&&w.lights===!0}this.getActiveCubeFace=function(){return Y},this.getActiveMipmapLevel=function(){return k},this.getRenderTarget=function(){return lt},this.setRenderTargetTextures=function(w,H,J){const $=zt.get(w);$.__autoAllocateDepthBuffer=w.resolveDepthBuffer===!1,$.__autoAllocateDepthBuffer===!1&&($.__useRenderToTexture=!1),zt.get(w.texture).__webglTexture=H,zt.get(w.depthTexture).__webglTexture=$.__autoAllocateDepthBuffer?void 0:J,$.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(w,H){const J=zt.get(w);J.__webglFramebuffer=H,J.__useDefaultFramebuffer=H===void 0},this.setRenderTarget=function(w,H=0,J=0){lt=w,Y=H,k=J;let $=null,q=!1,bt=!1;if(w){const wt=zt.get(w);if(wt.__useDefaultFramebuffer!==void 0){yt.bindFramebuffer(O.FRAMEBUFFER,wt.__webglFramebuffer),nt.copy(w.viewport),ut.copy(w.scissor),ot=w.scissorTest,yt.viewport(nt),yt.scissor(ut),yt.setScissorTest(ot),K=-1;return}else if(wt.__webglFramebuffer===void 0)Wt.setupRenderTarget(w);else if(wt.__hasExternalTextures)Wt.rebindTextures(w,zt.get(w.texture).__webglTexture,zt.get(w.depthTexture).__webglTexture);else if(w.depthBuffer){const Zt=w.depthTexture;if(wt.__boundDepthTexture!==Zt){if(Zt!==null&&zt.has(Zt)&&(w.width!==Zt.image.width||w.height!==Zt.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Wt.setupDepthRenderbuffer(w)}}const Pt=w.texture;(Pt.isData3DTexture||Pt.isDataArrayTexture||Pt.isCompressedArrayTexture)&&(bt=!0);const Bt=zt.get(w).__webglFramebuffer;w.isWebGLCubeRenderTarget?(Array.isArray(Bt[H])?$=Bt[H][J]:$=Bt[H],q=!0):w.samples>0&&Wt.useMultisampledRTT(w)===!1?$=zt.get(w).__webglMultisampledFramebuffer:Array.isArray(Bt)?$=Bt[J]:$=Bt,nt.copy(w.viewport),ut.copy(w.scissor),ot=w.scissorTest}else nt.copy(kt).multiplyScalar(Mt).floor(),ut.copy(oe).multiplyScalar(Mt).floor(),ot=se;if(J!==0&&($=B),yt.bindFramebuffer(O.FRAMEBUFFER,$)&&yt.drawBuffers(w,$),yt.viewport(nt),yt.scissor(ut),yt.setScissorTest(ot),q){const wt=zt.get(w.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_CUBE_MAP_POSITIVE_X+H,wt.__webglTexture,J)}else if(bt){const wt=H;for(let Pt=0;Pt<w.textures.length;Pt++){const Bt=zt.get(w.textures[Pt]);O.framebufferTextureLayer(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0+Pt,Bt.__webglTexture,J,wt)}}else if(w!==null&&J!==0){const wt=zt.get(w.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,wt.__webglTexture,J)}K=-1};function Zs(w){const H=zt.get(w);return(H.__readFormat!==w.format||H.__readType!==w.type)&&(H.__readFormat=w.format,H.__readType=w.type,H.__formatReadable=ne.textureFormatReadable(w.format),H.__typeReadable=ne.textureTypeReadable(w.type)),H}this.readRenderTargetPixels=function(w,H,J,$,q,bt,Ct,wt=0){if(!(w&&w.isWebGLRenderTarget)){ve("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Pt=zt.get(w).__webglFramebuffer;if(w.isWebGLCubeRenderTarget&&Ct!==void 0&&(Pt=Pt[Ct],Array.isArray(Pt)&&(Pt=Pt[0])),Pt){yt.bindFramebuffer(O.FRAMEBUFFER,Pt);try{const Bt=w.textures[wt],Zt=Bt.format,ce=Bt.type;w.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+wt);const Ot=Zs(Bt);if(Ot.__formatReadable===!1){ve("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(Ot.__typeReadable===!1){ve("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}H>=0&&H<=w.width-$&&J>=0&&J<=w.height-q&&O.readPixels(H,J,$,q,mt.convert(Zt),mt.convert(ce),bt)}finally{const Bt=lt!==null?zt.get(lt).__webglFramebuffer:null;yt.bindFramebuffer(O.FRAMEBUFFER,Bt)}}},this.readRenderTargetPixelsAsync=async function(w,H,J,$,q,bt,Ct,wt=0){if(!(w&&w.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Pt=zt.get(w).__webglFramebuffer;if(w.isWebGLCubeRenderTarget&&Ct!==void 0&&(Pt=Pt[Ct],Array.isArray(Pt)&&(Pt=Pt[0])),Pt)if(H>=0&&H<=w.width-$&&J>=0&&J<=w.height-q){yt.bindFramebuffer(O.FRAMEBUFFER,Pt);const Bt=w.textures[wt],Zt=Bt.format,ce=Bt.type;w.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+wt);const Ot=Zs(Bt);if(Ot.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(Ot.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");const he=O.createBuffer();O.bindBuffer(O.PIXEL_PACK_BUFFER,he),O.bufferData(O.PIXEL_PACK_BUFFER,bt.byteLength,O.STREAM_READ),O.readPixels(H,J,$,q,mt.convert(Zt),mt.convert(ce),0),O.bindBuffer(O.PIXEL_PACK_BUFFER,null);const Ve=lt!==null?zt.get(lt).__webglFramebuffer:null;yt.bindFramebuffer(O.FRAMEBUFFER,Ve);const be=O.fenceSync(O.SYNC_GPU_COMMANDS_COMPLETE,0);return O.flush(),await Fg(O,be,4),O.bindBuffer(O.PIXEL_PACK_BUFFER,he),O.getBufferSubData(O.PIXEL_PACK_BUFFER,0,bt),O.bindBuffer(O.PIXEL_PACK_BUFFER,null),O.deleteBuffer(he),O.deleteSync(be),bt}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(w,H=null,J=0){const $=Math.pow(2,-J),q=Math.floor(w.image.width*$),bt=Math.floor(w.image.height*$),Ct=H!==null?H.x:0,wt=H!==null?H.y:0;Wt.setTexture2D(w,0),O.copyTexSubImage2D(O.TEXTURE_2D,J,0,0,Ct,wt,q,bt),yt.unbindTexture()},this.copyTextureToTexture=function(w,H,J=null,$=null,q=0,bt=0){let Ct,wt,Pt,Bt,Zt,ce,Ot,he,Ve;const be=w.isCompressedTexture?w.mipmaps[bt]:w.image;if(J!==null)Ct=J.max.x-J.min.x,wt=J.max.y-J.min.y,Pt=J.isBox3?J.max.z-J.min.z:1,Bt=J.min.x,Zt=J.min.y,ce=J.isBox3?J.min.z:0;else{const re=Math.pow(2,-q);Ct=Math.floor(be.width*re),wt=Math.floor(be.height*re),w.isDataArrayTexture?Pt=be.depth:w.isData3DTexture?Pt=Math.floor(be.depth*re):Pt=1,Bt=0,Zt=0,ce=0}$!==null?(Ot=$.x,he=$.y,Ve=$.z):(Ot=0,he=0,Ve=0);const we=mt.convert(H.format),hn=mt.convert(H.type);let It;H.isData3DTexture?(Wt.setTexture3D(H,0),It=O.TEXTURE_3D):H.isDataArrayTexture||H.isCompressedArrayTexture?(Wt.setTexture2DArray(H,0),It=O.TEXTURE_2D_ARRAY):(Wt.setTexture2D(H,0),It=O.TEXTURE_2D),yt.activeTexture(O.TEXTURE0),yt.pixelStorei(O.UNPACK_FLIP_Y_WEBGL,H.flipY),yt.pixelStorei(O.UNPACK_PREMULTIPLY_ALPHA_WEBGL,H.premultiplyAlpha),yt.pixelStorei(O.UNPACK_ALIGNMENT,H.unpackAlignment);const en=yt.getParameter(O.UNPACK_ROW_LENGTH),fe=yt.getParameter(O.UNPACK_IMAGE_HEIGHT),Wi=yt.getParameter(O.UNPACK_SKIP_PIXELS),nn=yt.getParameter(O.UNPACK_SKIP_ROWS),Js=yt.getParameter(O.UNPACK_SKIP_IMAGES);yt.pixelStorei(O.UNPACK_ROW_LENGTH,be.width),yt.pixelStorei(O.UNPACK_IMAGE_HEIGHT,be.height),yt.pixelStorei(O.UNPACK_SKIP_PIXELS,Bt),yt.pixelStorei(O.UNPACK_SKIP_ROWS,Zt),yt.pixelStorei(O.UNPACK_SKIP_IMAGES,ce);const Ai=w.isDataArrayTexture||w.isData3DTexture,Xi=H.isDataArrayTexture||H.isData3DTexture;if(w.isDepthTexture){const re=zt.get(w),Ye=zt.get(H),In=zt.get(re.__renderTarget),Te=zt.get(Ye.__renderTarget);yt.bindFramebuffer(O.READ_FRAMEBUFFER,In.__webglFramebuffer),yt.bindFramebuffer(O.DRAW_FRAMEBUFFER,Te.__webglFramebuffer);for(let sn=0;sn<Pt;sn++)Ai&&(O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,zt.get(w).__webglTexture,q,ce+sn),O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,zt.get(H).__webglTexture,bt,Ve+sn)),O.blitFramebuffer(Bt,Zt,Bt+Ct,Zt+wt,Ot,he,Ot+Ct,he+wt,O.DEPTH_BUFFER_BIT,O.NEAREST);yt.bindFramebuffer(O.READ_FRAMEBUFFER,null),yt.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else if(q!==0||w.isRenderTargetTexture||zt.has(w)){const re=zt.get(w),Ye=zt.get(H);yt.bindFramebuffer(O.READ_FRAMEBUFFER,L),yt.bindFramebuffer(O.DRAW_FRAMEBUFFER,G);for(let In=0;In<Pt;In++)Ai?O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,re.__webglTexture,q,ce+In):O.framebufferTexture2D(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,re.__webglTexture,q),Xi?O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Ye.__webglTexture,bt,Ve+In):O.framebufferTexture2D(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,Ye.__webglTexture,bt),q!==0?O.blitFramebuffer(Bt,Zt,Bt+Ct,Zt+wt,Ot,he,Ot+Ct,he+wt,O.COLOR_BUFFER_BIT,O.NEAREST):Xi?O.copyTexSubImage3D(It,bt,Ot,he,Ve+In,Bt,Zt,Ct,wt):O.copyTexSubImage2D(It,bt,Ot,he,Bt,Zt,Ct,wt);yt.bindFramebuffer(O.READ_FRAMEBUFFER,null),yt.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else Xi?w.isDataTexture||w.isData3DTexture?O.texSubImage3D(It,bt,Ot,he,Ve,Ct,wt,Pt,we,hn,be.data):H.isCompressedArrayTexture?O.compressedTexSubImage3D(It,bt,Ot,he,Ve,Ct,wt,Pt,we,be.data):O.texSubImage3D(It,bt,Ot,he,Ve,Ct,wt,Pt,we,hn,be):w.isDataTexture?O.texSubImage2D(O.TEXTURE_2D,bt,Ot,he,Ct,wt,we,hn,be.data):w.isCompressedTexture?O.compressedTexSubImage2D(O.TEXTURE_2D,bt,Ot,he,be.width,be.height,we,be.data):O.texSubImage2D(O.TEXTURE_2D,bt,Ot,he,Ct,wt,we,hn,be);yt.pixelStorei(O.UNPACK_ROW_LENGTH,en),yt.pixelStorei(O.UNPACK_IMAGE_HEIGHT,fe),yt.pixelStorei(O.UNPACK_SKIP_PIXELS,Wi),yt.pixelStorei(O.UNPACK_SKIP_ROWS,nn),yt.pixelStorei(O.UNPACK_SKIP_IMAGES,Js),bt===0&&H.generateMipmaps===!0&&H.mipmapsAutoUpdate===!0&&O.generateMipmap(It),yt.unbindTexture()},this.initRenderTarget=function(w){zt.get(w).__webglFramebuffer===void 0&&Wt.setupRenderTarget(w)},this.initTexture=function(w){w.isCubeTexture?Wt.setTextureCube(w,0):w.isData3DTexture?Wt.setTexture3D(w,0):w.isDataArrayTexture||w.isCompressedArrayTexture?Wt.setTexture2DArray(w,0):Wt.setTexture2D(w,0),yt.unbindTexture()},this.resetState=function(){Y=0,k=0,lt=null,yt.reset(),St.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return bi}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(t){this._outputColorSpace=t;const e=this.getContext();e.drawingBufferColorSpace=me._getDrawingBufferColorSpace(t),e.unpackColorSpace=me._getUnpackColorSpace()}}const gd={type:"change"},Rh={type:"start"},vp={type:"end"},ro=new Oo,_d=new Si,MM=Math.cos(70*Mh.DEG2RAD),un=new V,Gn=2*Math.PI,ye={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},zl=1e-6;class xp extends A_{constructor(t,e=null){super(t,e),this.state=ye.NONE,this.target=new V,this.cursor=new V,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:yr.ROTATE,MIDDLE:yr.DOLLY,RIGHT:yr.PAN},this.touches={ONE:Sr.ROTATE,TWO:Sr.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new V,this._lastQuaternion=new rs,this._lastTargetPosition=new V,this._quat=new rs().setFromUnitVectors(t.up,new V(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new $u,this._sphericalDelta=new $u,this._scale=1,this._panOffset=new V,this._rotateStart=new Jt,this._rotateEnd=new Jt,this._rotateDelta=new Jt,this._panStart=new Jt,this._panEnd=new Jt,this._panDelta=new Jt,this._dollyStart=new Jt,this._dollyEnd=new Jt,this._dollyDelta=new Jt,this._dollyDirection=new V,this._mouse=new Jt,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=EM.bind(this),this._onPointerDown=yM.bind(this),this._onPointerUp=bM.bind(this),this._onContextMenu=LM.bind(this),this._onMouseWheel=AM.bind(this),this._onKeyDown=RM.bind(this),this._onTouchStart=CM.bind(this),this._onTouchMove=PM.bind(this),this._onMouseDown=wM.bind(this),this._onMouseMove=TM.bind(this),this._interceptControlDown=DM.bind(this),this._interceptControlUp=NM.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(t){this._cursorStyle=t,t==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(t){super.connect(t),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=ye.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(t){t.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=t}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(gd),this.update(),this.state=ye.NONE}pan(t,e){this._pan(t,e),this.update()}dollyIn(t){this._dollyIn(t),this.update()}dollyOut(t){this._dollyOut(t),this.update()}rotateLeft(t){this._rotateLeft(t),this.update()}rotateUp(t){this._rotateUp(t),this.update()}update(t=null){const e=this.object.position;un.copy(e).sub(this.target),un.applyQuaternion(this._quat),this._spherical.setFromVector3(un),this.autoRotate&&this.state===ye.NONE&&this._rotateLeft(this._getAutoRotationAngle(t)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let i=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(i)&&isFinite(s)&&(i<-Math.PI?i+=Gn:i>Math.PI&&(i-=Gn),s<-Math.PI?s+=Gn:s>Math.PI&&(s-=Gn),i<=s?this._spherical.theta=Math.max(i,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(i+s)/2?Math.max(i,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{const a=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=a!=this._spherical.radius}if(un.setFromSpherical(this._spherical),un.applyQuaternion(this._quatInverse),e.copy(this.target).add(un),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let a=null;if(this.object.isPerspectiveCamera){const o=un.length();a=this._clampDistance(o*this._scale);const c=o-a;this.object.position.addScaledVector(this._dollyDirection,c),this.object.updateMatrixWorld(),r=!!c}else if(this.object.isOrthographicCamera){const o=new V(this._mouse.x,this._mouse.y,0);o.unproject(this.object);const c=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=c!==this.object.zoom;const l=new V(this._mouse.x,this._mouse.y,0);l.unproject(this.object),this.object.position.sub(l).add(o),this.object.updateMatrixWorld(),a=un.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;a!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(a).add(this.object.position):(ro.origin.copy(this.object.position),ro.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(ro.direction))<MM?this.object.lookAt(this.target):(_d.setFromNormalAndCoplanarPoint(this.object.up,this.target),ro.intersectPlane(_d,this.target))))}else if(this.object.isOrthographicCamera){const a=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),a!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>zl||8*(1-this._lastQuaternion.dot(this.object.quaternion))>zl||this._lastTargetPosition.distanceToSquared(this.target)>zl?(this.dispatchEvent(gd),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(t){return t!==null?Gn/60*this.autoRotateSpeed*t:Gn/60/60*this.autoRotateSpeed}_getZoomScale(t){const e=Math.abs(t*.01);return Math.pow(.95,this.zoomSpeed*e)}_rotateLeft(t){this._sphericalDelta.theta-=t}_rotateUp(t){this._sphericalDelta.phi-=t}_panLeft(t,e){un.setFromMatrixColumn(e,0),un.multiplyScalar(-t),this._panOffset.add(un)}_panUp(t,e){this.screenSpacePanning===!0?un.setFromMatrixColumn(e,1):(un.setFromMatrixColumn(e,0),un.crossVectors(this.object.up,un)),un.multiplyScalar(t),this._panOffset.add(un)}_pan(t,e){const i=this.domElement;if(this.object.isPerspectiveCamera){const s=this.object.position;un.copy(s).sub(this.target);let r=un.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*t*r/i.clientHeight,this.object.matrix),this._panUp(2*e*r/i.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(t*(this.object.right-this.object.left)/this.object.zoom/i.clientWidth,this.object.matrix),this._panUp(e*(this.object.top-this.object.bottom)/this.object.zoom/i.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(t,e){if(!this.zoomToCursor)return;this._performCursorZoom=!0;const i=this.domElement.getBoundingClientRect(),s=t-i.left,r=e-i.top,a=i.width,o=i.height;this._mouse.x=s/a*2-1,this._mouse.y=-(r/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(t){return Math.max(this.minDistance,Math.min(this.maxDistance,t))}_handleMouseDownRotate(t){this._rotateStart.set(t.clientX,t.clientY)}_handleMouseDownDolly(t){this._updateZoomParameters(t.clientX,t.clientY),this._dollyStart.set(t.clientX,t.clientY)}_handleMouseDownPan(t){this._panStart.set(t.clientX,t.clientY)}_handleMouseMoveRotate(t){this._rotateEnd.set(t.clientX,t.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const e=this.domElement;this._rotateLeft(Gn*this._rotateDelta.x/e.clientHeight),this._rotateUp(Gn*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(t){this._dollyEnd.set(t.clientX,t.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(t){this._panEnd.set(t.clientX,t.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(t){this._updateZoomParameters(t.clientX,t.clientY),t.deltaY<0?this._dollyIn(this._getZoomScale(t.deltaY)):t.deltaY>0&&this._dollyOut(this._getZoomScale(t.deltaY)),this.update()}_handleKeyDown(t){let e=!1;switch(t.code){case this.keys.UP:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(Gn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),e=!0;break;case this.keys.BOTTOM:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(-Gn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),e=!0;break;case this.keys.LEFT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(Gn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),e=!0;break;case this.keys.RIGHT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(-Gn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),e=!0;break}e&&(t.preventDefault(),this.update())}_handleTouchStartRotate(t){if(this._pointers.length===1)this._rotateStart.set(t.pageX,t.pageY);else{const e=this._getSecondPointerPosition(t),i=.5*(t.pageX+e.x),s=.5*(t.pageY+e.y);this._rotateStart.set(i,s)}}_handleTouchStartPan(t){if(this._pointers.length===1)this._panStart.set(t.pageX,t.pageY);else{const e=this._getSecondPointerPosition(t),i=.5*(t.pageX+e.x),s=.5*(t.pageY+e.y);this._panStart.set(i,s)}}_handleTouchStartDolly(t){const e=this._getSecondPointerPosition(t),i=t.pageX-e.x,s=t.pageY-e.y,r=Math.sqrt(i*i+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enablePan&&this._handleTouchStartPan(t)}_handleTouchStartDollyRotate(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enableRotate&&this._handleTouchStartRotate(t)}_handleTouchMoveRotate(t){if(this._pointers.length==1)this._rotateEnd.set(t.pageX,t.pageY);else{const i=this._getSecondPointerPosition(t),s=.5*(t.pageX+i.x),r=.5*(t.pageY+i.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);const e=this.domElement;this._rotateLeft(Gn*this._rotateDelta.x/e.clientHeight),this._rotateUp(Gn*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(t){if(this._pointers.length===1)this._panEnd.set(t.pageX,t.pageY);else{const e=this._getSecondPointerPosition(t),i=.5*(t.pageX+e.x),s=.5*(t.pageY+e.y);this._panEnd.set(i,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(t){const e=this._getSecondPointerPosition(t),i=t.pageX-e.x,s=t.pageY-e.y,r=Math.sqrt(i*i+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);const a=(t.pageX+e.x)*.5,o=(t.pageY+e.y)*.5;this._updateZoomParameters(a,o)}_handleTouchMoveDollyPan(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enablePan&&this._handleTouchMovePan(t)}_handleTouchMoveDollyRotate(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enableRotate&&this._handleTouchMoveRotate(t)}_addPointer(t){this._pointers.push(t.pointerId)}_removePointer(t){delete this._pointerPositions[t.pointerId];for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId){this._pointers.splice(e,1);return}}_isTrackingPointer(t){for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId)return!0;return!1}_trackPointer(t){let e=this._pointerPositions[t.pointerId];e===void 0&&(e=new Jt,this._pointerPositions[t.pointerId]=e),e.set(t.pageX,t.pageY)}_getSecondPointerPosition(t){const e=t.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[e]}_customWheelEvent(t){const e=t.deltaMode,i={clientX:t.clientX,clientY:t.clientY,deltaY:t.deltaY};switch(e){case 1:i.deltaY*=16;break;case 2:i.deltaY*=100;break}return t.ctrlKey&&!this._controlActive&&(i.deltaY*=10),i}}function yM(n){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(n.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(n)&&(this._addPointer(n),n.pointerType==="touch"?this._onTouchStart(n):this._onMouseDown(n),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function EM(n){this.enabled!==!1&&(n.pointerType==="touch"?this._onTouchMove(n):this._onMouseMove(n))}function bM(n){switch(this._removePointer(n),this._pointers.length){case 0:this.domElement.releasePointerCapture(n.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(vp),this.state=ye.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:const t=this._pointers[0],e=this._pointerPositions[t];this._onTouchStart({pointerId:t,pageX:e.x,pageY:e.y});break}}function wM(n){let t;switch(n.button){case 0:t=this.mouseButtons.LEFT;break;case 1:t=this.mouseButtons.MIDDLE;break;case 2:t=this.mouseButtons.RIGHT;break;default:t=-1}switch(t){case yr.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(n),this.state=ye.DOLLY;break;case yr.ROTATE:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=ye.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=ye.ROTATE}break;case yr.PAN:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=ye.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=ye.PAN}break;default:this.state=ye.NONE}this.state!==ye.NONE&&this.dispatchEvent(Rh)}function TM(n){switch(this.state){case ye.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(n);break;case ye.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(n);break;case ye.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(n);break}}function AM(n){this.enabled===!1||this.enableZoom===!1||this.state!==ye.NONE||(n.preventDefault(),this.dispatchEvent(Rh),this._handleMouseWheel(this._customWheelEvent(n)),this.dispatchEvent(vp))}function RM(n){this.enabled!==!1&&this._handleKeyDown(n)}function CM(n){switch(this._trackPointer(n),this._pointers.length){case 1:switch(this.touches.ONE){case Sr.ROTATE:if(this.enableRotate===!1){this.state=ye.NONE;break}this._handleTouchStartRotate(n),this.state=ye.TOUCH_ROTATE;break;case Sr.PAN:if(this.enablePan===!1){this.state=ye.NONE;break}this._handleTouchStartPan(n),this.state=ye.TOUCH_PAN;break;default:this.state=ye.NONE}break;case 2:switch(this.touches.TWO){case Sr.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(n),this.state=ye.TOUCH_DOLLY_PAN;break;case Sr.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(n),this.state=ye.TOUCH_DOLLY_ROTATE;break;default:this.state=ye.NONE}break;default:this.state=ye.NONE}this.state!==ye.NONE&&this.dispatchEvent(Rh)}function PM(n){switch(this._trackPointer(n),this.state){case ye.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(n),this.update();break;case ye.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(n),this.update();break;case ye.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(n),this.update();break;case ye.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(n),this.update();break;default:this.state=ye.NONE}}function LM(n){this.enabled!==!1&&n.preventDefault()}function DM(n){n.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function NM(n){n.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}const IM=new Th(-1,1,1,-1,0,1);class UM extends ln{constructor(){super(),this.setAttribute("position",new We([-1,3,0,-1,-1,0,3,-1,0],3)),this.setAttribute("uv",new We([0,2,0,0,2,0],2))}}const FM=new UM;class OM{constructor(t){this._mesh=new bn(FM,t)}dispose(){this._mesh.geometry.dispose()}render(t){t.render(this._mesh,IM)}get material(){return this._mesh.material}set material(t){this._mesh.material=t}}const jr=new V,vd=new V,xd=new V,ao=new V,ta=new V,kl=new V,oo=new V,Hl=new rs;function Sd(n,t,e,i,s=!1){const r=t,a=e,o=i,c=n.position,l=n.near,h=n.far;ao.copy(a).sub(r).normalize(),ta.copy(o).sub(r).normalize(),kl.crossVectors(ao,ta).normalize(),jr.copy(r).sub(c),vd.copy(a).sub(c),xd.copy(o).sub(c);const d=-jr.dot(kl),u=ao.dot(jr)*l/d,m=ao.dot(vd)*l/d,v=ta.dot(jr)*l/d,M=ta.dot(xd)*l/d;Hl.setFromUnitVectors(oo.set(0,1,0),ta),n.quaternion.setFromUnitVectors(oo.set(0,0,1).applyQuaternion(Hl),kl).multiply(Hl),n.projectionMatrix.set(2*l/(m-u),0,(m+u)/(m-u),0,0,2*l/(M-v),(M+v)/(M-v),0,0,0,(h+l)/(l-h),2*h*l/(l-h),0,0,-1,0),n.projectionMatrixInverse.copy(n.projectionMatrix).invert(),s&&(n.fov=Mh.RAD2DEG/Math.min(1,n.aspect)*Math.atan((oo.copy(a).sub(r).length()+oo.copy(o).sub(r).length())/jr.length()))}const ii=new Ln,si=new Ln,Md=new V,yd=new V,lo=new V,Gl=new V,Vl=new V,Wl=new V,Bs=new V,ea=new V,Xl=new V;class BM{constructor(t,e=512,i=512){this.colorMatrixLeft=new te().fromArray([.4561,-.0400822,-.0152161,.500484,-.0378246,-.0205971,.176381,-.0157589,-.00546856]),this.colorMatrixRight=new te().fromArray([-.0434706,.378476,-.0721527,-.0879388,.73364,-.112961,-.00155529,-.0184503,1.2264]),this.eyeSep=.064,this.planeDistance=.5;const s={minFilter:zn,magFilter:wn,format:Ei},r=new hi(e,i,s),a=new hi(e,i,s);ii.layers.enable(1),si.layers.enable(2);const o=new As({uniforms:{mapLeft:{value:r.texture},mapRight:{value:a.texture},colorMatrixLeft:{value:this.colorMatrixLeft},colorMatrixRight:{value:this.colorMatrixRight}},vertexShader:["varying vec2 vUv;","void main() {","	vUv = vec2( uv.x, uv.y );","	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );","}"].join(`
`),fragmentShader:["uniform sampler2D mapLeft;","uniform sampler2D mapRight;","varying vec2 vUv;","uniform mat3 colorMatrixLeft;","uniform mat3 colorMatrixRight;","void main() {","	vec2 uv = vUv;","	vec4 colorL = texture2D( mapLeft, uv );","	vec4 colorR = texture2D( mapRight, uv );","	vec3 color = clamp(","			colorMatrixLeft * colorL.rgb +","			colorMatrixRight * colorR.rgb, 0., 1. );","	gl_FragColor = vec4(","			color.r, color.g, color.b,","			max( colorL.a, colorR.a ) );","	#include <tonemapping_fragment>","	#include <colorspace_fragment>","}"].join(`
`)}),c=new OM(o);this.setSize=function(l,h){t.setSize(l,h);const d=t.getPixelRatio();r.setSize(l*d,h*d),a.setSize(l*d,h*d)},this.render=function(l,h){const d=t.getRenderTarget();l.matrixWorldAutoUpdate===!0&&l.updateMatrixWorld(),h.parent===null&&h.matrixWorldAutoUpdate===!0&&h.updateMatrixWorld(),h.matrixWorld.extractBasis(Bs,ea,Xl),Bs.normalize(),ea.normalize(),Xl.normalize();const u=this.eyeSep/2;Md.copy(h.position).addScaledVector(Bs,-u),yd.copy(h.position).addScaledVector(Bs,u),lo.copy(h.position).addScaledVector(Xl,-this.planeDistance);const m=this.planeDistance*Math.tan(Mh.DEG2RAD*h.fov/2),v=m*h.aspect;Gl.copy(lo).addScaledVector(Bs,-v).addScaledVector(ea,-m),Vl.copy(lo).addScaledVector(Bs,v).addScaledVector(ea,-m),Wl.copy(lo).addScaledVector(Bs,-v).addScaledVector(ea,m),ii.position.copy(Md),ii.near=h.near,ii.far=h.far,Sd(ii,Gl,Vl,Wl,!0),ii.matrixWorld.compose(ii.position,ii.quaternion,ii.scale),ii.matrixWorldInverse.copy(ii.matrixWorld).invert(),si.position.copy(yd),si.near=h.near,si.far=h.far,Sd(si,Gl,Vl,Wl,!0),si.matrixWorld.compose(si.position,si.quaternion,si.scale),si.matrixWorldInverse.copy(si.matrixWorld).invert(),t.setRenderTarget(r),t.clear(),t.render(l,ii),t.setRenderTarget(a),t.clear(),t.render(l,si),t.setRenderTarget(null),c.render(t),t.setRenderTarget(d)},this.dispose=function(){r.dispose(),a.dispose(),o.dispose(),c.dispose()}}}class zM{constructor(t){const e=new b_;e.aspect=.5;const i=new Jt;this.setEyeSeparation=function(s){e.eyeSep=s},this.setSize=function(s,r){t.setSize(s,r)},this.render=function(s,r){s.matrixWorldAutoUpdate===!0&&s.updateMatrixWorld(),r.parent===null&&r.matrixWorldAutoUpdate===!0&&r.updateMatrixWorld(),e.update(r);const a=t.autoClear;t.getSize(i),t.autoClear=!1,t.clear(),t.setScissorTest(!0),t.setScissor(0,0,i.width/2,i.height),t.setViewport(0,0,i.width/2,i.height),t.render(s,e.cameraL),t.setScissor(i.width/2,0,i.width/2,i.height),t.setViewport(i.width/2,0,i.width/2,i.height),t.render(s,e.cameraR),t.setScissorTest(!1),t.autoClear=a}}}const co=(n,t)=>n[0]*t[0]+n[1]*t[1]+n[2]*t[2],$l=(n,t)=>[n[0]+t[0],n[1]+t[1],n[2]+t[2]],Yl=(n,t)=>[n[0]-t[0],n[1]-t[1],n[2]-t[2]],Fi=(n,t)=>[n[0]*t,n[1]*t,n[2]*t];function kM(n,t){return 4*Math.sqrt(Math.max(Math.abs(t),1)*Math.max(n,0))}function HM(n,t,e,i,s){const r=Math.hypot(...e),a=Math.hypot(...n.direction);if(!(r>0)||!(a>0)||!(i>0)||!Number.isFinite(r)||!Number.isFinite(a)||![...t,...n.origin].every(Number.isFinite))return null;const o=Fi(e,1/r),c=Fi(n.direction,1/a),l=$l(t,e),h=Yl(l,n.origin),d=co(o,c),u=Math.abs(d)>1e-9?co(o,h)/d:-1,m=u>0?$l(n.origin,Fi(c,u)):$l(n.origin,Fi(c,Math.max(co(h,c),0)));let v=Yl(m,l);v=Yl(v,Fi(o,co(v,o)));let M=Fi(v,1/i);const p=Math.hypot(...M);if(!Number.isFinite(p))return null;const f=Math.max(s,0);return p>f?(M=p>0?Fi(M,f/p):[0,0,0],{v:M,speed:f,capped:!0}):{v:M,speed:p,capped:!1}}function GM(n,t,e,i){const s=Fi(t,e),r=Math.hypot(...s);if(r>=i)return s;if(r>1e-12*i)return Fi(s,i/r);const a=[-n[1],n[0],0],o=Math.hypot(...a);return o>1e-12*Math.hypot(...n)&&o>0?Fi(a,i/o):[i,0,0]}function VM(n,t,e){const i=n.intersectSphere(new Ta(t,e),new V);if(i!==null)return i.sub(t);const s=n.closestPointToPoint(t,new V).sub(t),r=s.length();return r>0?s.multiplyScalar(e/r):new V(0,0,-e)}class WM{constructor(t,e,i,s,r,a){this.canvas=t,this.camera=e,this.controls=i,this.bob=s,this.onDrag=r,this.sphere=a,t.addEventListener("pointerdown",o=>this.down(o),{capture:!0}),t.addEventListener("pointermove",o=>this.move(o)),t.addEventListener("pointerup",o=>this.up(o)),t.addEventListener("pointercancel",o=>this.up(o))}canvas;camera;controls;bob;onDrag;sphere;dragging=!1;raycaster=new sp;get active(){return this.dragging}ray(t){const e=this.canvas.getBoundingClientRect(),i=new Jt((t.clientX-e.left)/e.width*2-1,-((t.clientY-e.top)/e.height)*2+1);return this.raycaster.setFromCamera(i,this.camera),this.raycaster.ray}position(t){const{pivot:e,length:i}=this.sphere(),s=VM(this.ray(t),e,i);return[s.x,s.y,s.z]}down(t){t.button!==0||!this.bob.visible||(this.ray(t),this.raycaster.intersectObject(this.bob,!1).length!==0&&(this.dragging=!0,this.controls.enabled=!1,this.canvas.setPointerCapture?.(t.pointerId),t.stopImmediatePropagation(),this.onDrag(this.position(t),"start")))}move(t){this.dragging&&this.onDrag(this.position(t),"move")}up(t){this.dragging&&(this.dragging=!1,this.controls.enabled=!0,this.onDrag(this.position(t),"end"))}}class XM{constructor(t,e,i,s,r,a,o,c){this.canvas=t,this.camera=e,this.controls=i,this.handle=s,this.occluder=r,this.grabRadius=a,this.pullBasis=o,this.onPull=c,t.addEventListener("pointerdown",l=>this.down(l),{capture:!0}),t.addEventListener("pointermove",l=>this.move(l)),t.addEventListener("pointerup",l=>this.up(l)),t.addEventListener("pointercancel",l=>this.up(l))}canvas;camera;controls;handle;occluder;grabRadius;pullBasis;onPull;basis=null;moved=!1;raycaster=new sp;tmp=new V;get active(){return this.basis!==null}ray(t){const e=this.canvas.getBoundingClientRect(),i=new Jt((t.clientX-e.left)/e.width*2-1,-((t.clientY-e.top)/e.height)*2+1);return this.raycaster.setFromCamera(i,this.camera),this.raycaster.ray}pulled(t){if(this.basis===null)return null;const e=this.ray(t),{pivot:i,x:s,arrowScale:r,vmax:a}=this.basis;return HM({origin:[e.origin.x,e.origin.y,e.origin.z],direction:[e.direction.x,e.direction.y,e.direction.z]},i,s,r,a)}down(t){if(t.button!==0||!this.handle.visible)return;const e=this.ray(t),i=this.handle.getWorldPosition(this.tmp),s=this.grabRadius();if(e.distanceToPoint(i)>s)return;const r=this.raycaster.intersectObject(this.occluder,!1)[0];if(r!==void 0&&r.distance<i.sub(e.origin).dot(e.direction)-s)return;const a=this.pullBasis();a!==null&&(this.basis=a,this.moved=!1,this.controls.enabled=!1,this.canvas.setPointerCapture?.(t.pointerId),t.stopImmediatePropagation(),this.onPull(a.x,null,"start"))}move(t){this.basis!==null&&(this.moved=!0,this.onPull(this.basis.x,this.pulled(t),"move"))}up(t){if(this.basis===null)return;const e=this.moved?this.pulled(t):null,i=this.basis.x;this.basis=null,this.controls.enabled=!0,this.onPull(i,e,"end")}}const Ed=512,da=4e3,$M=4e3,YM=2e5,qM=3,KM=["t [s]","x1 [m]","x2 [m]","x3 [m]","v1 [m/s]","v2 [m/s]","v3 [m/s]","energy [J]","j3 [kg m^2/s]","tension [N]","power [W]","a1 [m/s^2]","a2 [m/s^2]","a3 [m/s^2]","pivot1 [m]","pivot2 [m]","pivot3 [m]","taut [1]"];function bd(){return{t:[],dE:[],dJ3:[],z:[],zdot:[],tension:[]}}function Qi(n,t,e){return n+(t-n)*e}function ZM(n,t,e){const i=(o,c)=>[Qi(o[0],c[0],e),Qi(o[1],c[1],e),Qi(o[2],c[2],e)],s=i(n.x,t.x),r=Qi(Math.hypot(...n.x),Math.hypot(...t.x),e),a=Math.hypot(...s);if(a>0)for(let o=0;o<3;o++)s[o]=s[o]*(r/a);return{t:Qi(n.t,t.t,e),x:s,v:i(n.v,t.v),energy:Qi(n.energy,t.energy,e),j3:Qi(n.j3,t.j3,e),tension:Qi(n.tension,t.tension,e),power:Qi(n.power,t.power,e),a:i(n.a,t.a),pivot:i(n.pivot,t.pivot),taut:n.taut&&t.taut}}function JM(n,t,e){return n===null||t.epoch!==n.epoch||e!==null&&t.t<e}function wd(n,t,e){let i=0,s=n.length;for(;i<s;){const r=i+s>>1,a=n[r].t;(e?a<t:a<=t)?i=r+1:s=r}return i}class QM{status=null;frames=[];trail=[];history=bd();trajectory=[];trajectoryTruncated=!1;reference=null;tensionExtremes=null;playT=null;exact=null;exactError=null;errors=[];events=[];connected=!1;tickHz=60;historyStride=1;historyCount=0;disconnected=!1;listeners=new Set;subscribe(t){return this.listeners.add(t),()=>this.listeners.delete(t)}emit(){for(const t of this.listeners)t()}onStatus(t){const e=this.disconnected||JM(this.status,t,this.latest()?.t??null);this.disconnected=!1,this.status=t,e&&this.clear(),this.emit()}clear(){this.frames=[],this.trail=[],this.history=bd(),this.trajectory=[],this.trajectoryTruncated=!1,this.reference=null,this.tensionExtremes=null,this.playT=null,this.exact=null,this.exactError=null,this.events=[],this.historyStride=1,this.historyCount=0}onError(t){this.errors.push(t),this.errors.length>20&&this.errors.shift(),this.emit()}onEvent(t){const e=this.events;this.events=Im(e,t,this.status?.epoch??null),this.events!==e&&this.emit()}setConnected(t){this.connected=t,t||(this.disconnected=!0),this.emit()}setExact(t,e=null){this.exact=t,this.exactError=e,this.emit()}onFrames(t){for(const e of t){const i=this.frames[this.frames.length-1];if(i!==void 0&&e.t<i.t)continue;i!==void 0&&e.t===i.t&&this.frames.pop(),this.frames.push(e),this.reference===null&&(this.reference={energy:e.energy,j3:e.j3});const s=this.tensionExtremes;s===null?this.tensionExtremes={min:e.tension,tMin:e.t,max:e.tension,tMax:e.t}:(e.tension<s.min&&([s.min,s.tMin]=[e.tension,e.t]),e.tension>s.max&&([s.max,s.tMax]=[e.tension,e.t])),this.pushTrail(e),this.pushHistory(e),this.trajectory.length<YM?this.trajectory.push(e):this.trajectoryTruncated=!0,this.playT===null&&(this.playT=e.t)}this.frames.length>Ed&&this.frames.splice(0,this.frames.length-Ed)}pushTrail(t){const e=this.trail[this.trail.length-1];e!==void 0&&e.t===t.t&&this.trail.pop(),this.trail.push(t),this.trail.length>da&&this.trail.splice(0,this.trail.length-da)}pushHistory(t){const e=this.reference;if(e===null)return;const i=this.history;if(!(i.t.length>0&&t.t<=i.t[i.t.length-1])&&this.historyCount++%this.historyStride===0&&(i.t.push(t.t),i.dE.push(t.energy-e.energy),i.dJ3.push(t.j3-e.j3),i.z.push(t.x[2]),i.zdot.push(t.v[2]),i.tension.push(t.tension),i.t.length>$M)){const s=r=>r.filter((a,o)=>o%2===0);this.history={t:s(i.t),dE:s(i.dE),dJ3:s(i.dJ3),z:s(i.z),zdot:s(i.zdot),tension:s(i.tension)},this.historyStride*=2,this.historyCount=1}}latest(){return this.frames[this.frames.length-1]??null}advancePlayhead(t){const e=this.latest(),i=this.frames[0];if(e==null||i===void 0)return this.playT=null;const s=this.status;if(s===null||s.paused||this.playT===null)return this.playT=e.t,this.playT;const r=qM*s.time_scale/this.tickHz;let a=this.playT+Math.max(0,t)*s.time_scale;return a=Math.min(a,e.t),a=Math.max(a,e.t-r,i.t),this.playT=a,a}displayed(){const t=this.playT,e=this.frames;if(t===null||e.length===0)return null;const i=e[e.length-1];if(t>=i.t)return i;let s=0,r=e.length-1;if(t<=e[0].t)return e[0];for(;r-s>1;){const l=s+r>>1;e[l].t<=t?s=l:r=l}const a=e[s],o=e[r],c=o.t-a.t;return ZM(a,o,c>0?(t-a.t)/c:1)}trailRange(t){const e=this.playT;if(e===null)return{start:0,end:0};const i=wd(this.trail,e,!1),s=wd(this.trail,e-t,!0);return{start:Math.min(s,i),end:i}}trailWindow(t){const{start:e,end:i}=this.trailRange(t);return this.trail.slice(e,i)}toCSV(){const t=this.status,e={source:"pendulab lab",scenario:t?.scenario??null,params:t?.params??null,model:t?.model??null,model_params:t?.model_params??null,method:t?.method??null,dt:t?.dt??null,truncated:this.trajectoryTruncated},i=KM.join(","),s=this.trajectory.map(r=>[r.t,...r.x,...r.v,r.energy,r.j3,r.tension,r.power,...r.a,...r.pivot,r.taut?1:0].map(a=>String(a)).join(","));return[`# ${JSON.stringify(e)}`,i,...s].join(`
`)+`
`}}const Td=(n,t)=>[n[1]*t[2]-n[2]*t[1],n[2]*t[0]-n[0]*t[2],n[0]*t[1]-n[1]*t[0]],aa=(n,t)=>[n[0]*t,n[1]*t,n[2]*t],jM=(n,t)=>[n[0]-t[0],n[1]-t[1],n[2]-t[2]];function ty(n){const t=[n?.gravity_x??0,n?.gravity_y??0,n?.gravity_z??-1],e=Math.hypot(...t);return e>0?aa(t,1/e):[0,0,-1]}function ey(n,t,e,i,s){const r=Math.hypot(...n.x),a=aa(n.v,t),o=aa(n.a,t),c=jM(n.x,s);return{velocity:n.v,momentum:a,gravity:aa(i,t*e),tension:r>0?aa(n.x,-n.tension/r):[0,0,0],net:o,angularMomentum:Td(c,a),torque:Td(c,o)}}function ql(n,t,e){const i=Math.max(Math.abs(e),1),s=.5*n/(t*i),r=Math.sqrt(i/n);return{velocity:.25,momentum:.25,gravity:s,tension:s,net:s,angularMomentum:.5*n/(t*n*n*r),torque:s/n}}const Sp=(n,t)=>[n[0]-t[0],n[1]-t[1],n[2]-t[2]],Ma=n=>Math.hypot(n[0],n[1],n[2]),ya=(n,t)=>[n[0]*t,n[1]*t,n[2]*t],Jc=(n,t)=>[n[1]*t[2]-n[2]*t[1],n[2]*t[0]-n[0]*t[2],n[0]*t[1]-n[1]*t[0]];function Mp(n,t){const e=t[0]*n[0]+t[1]*n[1]+t[2]*n[2];let i=Sp(t,ya(n,e));return Ma(i)<1e-9&&(i=Math.abs(n[0])<.9?Jc(n,[1,0,0]):Jc(n,[0,1,0])),ya(i,1/Ma(i))}function ny(n,t,e,i){const s=Ma(n);if(!(s>0))return[[0,0,0],[...n]];const r=ya(n,1/s),a=Mp(r,[0,0,1]),o=Jc(r,a),c=[];for(let l=0;l<=i;l++){const h=l/i,d=e*Math.min(1,h/.05,(1-h)/.05),u=2*Math.PI*t*h,[m,v]=[Math.cos(u)*d,Math.sin(u)*d];c.push([n[0]*h+a[0]*m+o[0]*v,n[1]*h+a[1]*m+o[1]*v,n[2]*h+a[2]*m+o[2]*v])}return c}function iy(n){let t=0;for(let e=1;e<n.length;e++)t+=Ma(Sp(n[e],n[e-1]));return t}function Ad(n,t,e){const i=[];for(let s=0;s<=e;s++){const r=s/e,[a,o]=[2*r*(1-r),r*r];i.push([t[0]*a+n[0]*o,t[1]*a+n[1]*o,t[2]*a+n[2]*o])}return i}function sy(n,t,e,i=[0,0,-1]){const s=Ma(n),r=ya(n,.5);if(!(s>0)||s>=t)return Ad(n,r,e);const a=Mp(ya(n,1/s),i),o=h=>Ad(n,[r[0]+a[0]*h,r[1]+a[1]*h,r[2]+a[2]*h],e);let[c,l]=[0,t];for(let h=0;h<40&&l-c>1e-4*t;h++){const d=.5*(c+l);iy(o(d))<t?c=d:l=d}return o(.5*(c+l))}const Rd=400,Cd=48;class ry{group=new Mr;coil;slack;constructor(){this.coil=new Xs(new ln().setFromPoints(Array.from({length:Rd+1},()=>new V)),new Ts({color:14211288})),this.slack=new Xs(new ln().setFromPoints(Array.from({length:Cd+1},()=>new V)),new x_({color:15918793,dashSize:.04,gapSize:.03}));for(const t of[this.coil,this.slack])t.frustumCulled=!1,t.visible=!1;this.group.add(this.coil,this.slack)}update(t,e,i,s,r){if(this.coil.visible=t==="coil",this.slack.visible=t==="slack string",this.group.position.set(...i),t==="coil"&&this.fill(this.coil,ny(e,14,.035*s,Rd)),t==="slack string"){this.fill(this.slack,sy(e,s,Cd,r));const a=this.slack.material;a.dashSize=.04*s,a.gapSize=.03*s,this.slack.computeLineDistances()}}fill(t,e){const i=t.geometry.getAttribute("position");e.forEach((s,r)=>i.setXYZ(r,s[0],s[1],s[2])),i.needsUpdate=!0}}const ay=/swiftshader|llvmpipe|softpipe|software|basic render driver|lavapipe/i;function oy(n){return n!==null&&ay.test(n)}function ly(n,t){return 1-(1-n)**t}function cy(n,t){const e=oy(n),i=Number.isFinite(t)&&t>0?t:1;return{renderer:n,software:e,antialias:!e,pixelRatio:Math.min(i,e?1:2),reachLayers:e?1:2}}function hy(){const n=document.createElement("canvas"),t=n.getContext("webgl2")??n.getContext("webgl");if(t===null)return null;let e=t.getParameter(t.RENDERER);if(typeof e!="string"||e===""||/^webkit webgl$/i.test(e)){const i=t.getExtension("WEBGL_debug_renderer_info");i!==null&&(e=t.getParameter(i.UNMASKED_RENDERER_WEBGL))}return t.getExtension("WEBGL_lose_context")?.loseContext(),typeof e=="string"&&e!==""&&!/^webkit webgl$/i.test(e)?e:null}const uy=["off","anaglyph","side by side"],dy={trail:!0,trailSeconds:10,sphere:!0,axes:!0,velocity:!0,momentum:!1,gravity:!1,tension:!1,net:!1,angularMomentum:!1,torque:!1,originX:0,originY:0,originZ:0,stereo:"off"},fy={velocity:14711807,momentum:10194175,gravity:16757575,tension:16735603,net:16777215,angularMomentum:5102016,torque:16769357},py=["angularMomentum","torque"],Pd=new le(1119259),Ld=.06,my=new le(5882879),gy=new V(0,1,0),_y=.025,vy=.06,xy=.085,Sy={frames:[],start:0,end:0};function My(n){const t=new T_(new V(1,0,0),new V,1,n);return t.visible=!1,t}class yy{constructor(t,e){this.container=t,this.renderer=new _p({antialias:e.antialias}),this.renderer.setPixelRatio(e.pixelRatio),this.renderer.domElement.id="scene-canvas",t.appendChild(this.renderer.domElement),this.scene.background=Pd,this.camera=new Ln(40,1,.01,1e3),this.camera.up.set(0,0,1),this.controls=new xp(this.camera,this.renderer.domElement),this.controls.enableDamping=!0,this.scene.add(new E_(16777215,.6));const i=new y_(16777215,1.6);i.position.set(2,-3,4),this.scene.add(i),this.sphere=new bn(new Gs(1,48,32),new ys({color:9417727,transparent:!0,opacity:e.reachLayers===1?ly(Ld,2):Ld,depthWrite:!1,side:e.reachLayers===2?ci:Es}));const s=new ln().setFromPoints(Array.from({length:128},(a,o)=>{const c=2*Math.PI*o/128;return new V(Math.cos(c),Math.sin(c),0)}));this.equator=new u_(s,new Ts({color:9417727,transparent:!0,opacity:.25})),this.pivot=new bn(new Gs(.02,16,12),new Il({color:13421772})),this.rod=new bn(new Bo(1,1,1,12),new Il({color:14211288,metalness:.6,roughness:.3})),this.bob=new bn(new Gs(1,32,24),new Il({color:16747586,roughness:.35})),this.axes=new rp(1.3),this.handle=new bn(new Gs(1,16,12),new ys({color:15911167})),this.handle.name="velocity handle",this.handle.visible=!1,this.trailPositions=new Float32Array(3*(da+1)),this.trailColors=new Float32Array(3*(da+1));const r=new ln;r.setAttribute("position",new ns(this.trailPositions,3)),r.setAttribute("color",new ns(this.trailColors,3)),r.setDrawRange(0,0),this.trail=new Xs(r,new Ts({vertexColors:!0})),this.trail.frustumCulled=!1,this.scene.add(this.sphere,this.equator,this.pivot,this.rod,this.bob,this.axes,this.trail,this.tether.group,this.handle,...Object.values(this.arrows)),this.setLength(1),this.resetCamera(),new ResizeObserver(()=>this.resize()).observe(t),this.resize()}container;renderer;camera;controls;scene=new Kf;sphere;equator;rod;bob;pivot;axes;trail;trailPositions;trailColors;trailColored=-1;tmpX=new V;tmpBob=new V;tmpDir=new V;tmpVec=new V;tmpOrigin=new V;arrows=Object.fromEntries(Object.entries(fy).map(([t,e])=>[t,My(e)]));length=1;extent=1;stereo="off";anaglyph=null;sideBySide=null;drag=null;pull=null;handle;drawn=null;velocityScale=ql(1,1,9.81).velocity;gNow=9.81;tmpHandle=new V;pivotNow=new V;topView=!1;tether=new ry;model="ideal";invalid=!0;setLength(t){if(!(t>0))return;const e=Math.abs(t-this.length)>1e-12*t;this.length=t,e&&(this.extent=t),this.sphere.scale.setScalar(t),this.equator.scale.setScalar(t),this.pivot.scale.setScalar(t),this.bob.scale.setScalar(.05*t),this.handle.scale.setScalar(_y*t),this.axes.scale.setScalar(t),e&&this.resetCamera(),this.invalid=!0}fit(t){Math.abs(t-this.extent)<=.2*this.extent||(this.extent=t,this.resetCamera())}resetCamera(){const t=this.extent;this.topView?this.camera.position.set(0,-1e-4*t,5.2*t):this.camera.position.set(3.3*t,-3.9*t,1.5*t),this.controls.target.set(0,0,0),this.camera.near=.01*this.length,this.camera.far=100*t,this.camera.updateProjectionMatrix(),this.controls.update(),this.invalid=!0}setModel(t){this.invalid||=t!==this.model,this.model=t}setTopView(t){this.topView=t,this.resetCamera()}enableDrag(t,e){const i=this.renderer.domElement;this.pull=new XM(i,this.camera,this.controls,this.handle,this.bob,()=>vy*this.length,()=>this.pullBasis(),e),this.drag=new WM(i,this.camera,this.controls,this.bob,t,()=>({pivot:this.pivotNow,length:this.length}))}pullBasis(){const t=this.drawn;return t===null?null:{pivot:[...t.pivot],x:[...t.x],arrowScale:this.velocityScale,vmax:kM(this.length,this.gNow)}}onScreen(t){if(!t.visible)return null;const e=t.position.clone().project(this.camera),i=this.renderer.domElement.getBoundingClientRect();return{x:i.left+(e.x+1)/2*i.width,y:i.top+(1-e.y)/2*i.height}}bobOnScreen(){return this.onScreen(this.bob)}handleOnScreen(){return this.onScreen(this.handle)}setStereo(t){this.stereo=t,t==="anaglyph"&&this.anaglyph===null&&(this.anaglyph=new BM(this.renderer)),t==="side by side"&&this.sideBySide===null&&(this.sideBySide=new zM(this.renderer)),this.resize()}resize(){const t=Math.max(1,this.container.clientWidth),e=Math.max(1,this.container.clientHeight);this.renderer.setSize(t,e,!1),this.stereo==="anaglyph"&&this.anaglyph?.setSize(t,e),this.stereo==="side by side"&&this.sideBySide?.setSize(t,e),this.renderer.domElement.style.width="",this.renderer.domElement.style.height="",this.camera.aspect=t/e,this.camera.updateProjectionMatrix(),this.invalid=!0}update(t,e,i,s,r,a){this.sphere.visible=i.sphere,this.equator.visible=i.sphere,this.axes.visible=i.axes;const o=t!==null,c=yf(this.model,t?.taut??!0);if(this.rod.visible=o&&(c==="rod"||c==="taut string"),this.bob.visible=o,this.drawn=t,this.gNow=r,this.velocityScale=ql(this.length,s,r).velocity,this.handle.visible=o&&i.velocity,t===null){this.tether.update("rod",[0,0,0],[0,0,0],this.length,a),this.trail.geometry.setDrawRange(0,0);for(const A of Object.values(this.arrows))A.visible=!1;return}const l=this.pivotNow.fromArray(t.pivot);this.fit(this.length+l.length());for(const A of[this.sphere,this.equator,this.pivot])A.position.copy(l);const h=this.tmpX.fromArray(t.x),d=h.length(),u=this.tmpBob.copy(h).add(l);if(this.bob.position.copy(u),d>0){this.rod.position.copy(h).multiplyScalar(.5).add(l),this.rod.quaternion.setFromUnitVectors(gy,this.tmpDir.copy(h).divideScalar(d));const A=c==="taut string"?.003:.008;this.rod.scale.set(A*this.length,d,A*this.length)}const m=r<0?[-a[0],-a[1],-a[2]]:a;if(this.tether.update(c,t.x,t.pivot,this.length,m),this.updateTrail(i.trail?e:Sy,t),this.handle.visible){const A=GM(t.x,t.v,this.velocityScale,xy*this.length);this.handle.position.copy(this.tmpHandle.fromArray(A).add(u))}const v=Object.keys(this.arrows);if(!v.some(A=>i[A])){for(const A of v)this.arrows[A].visible=!1;return}const M=[i.originX,i.originY,i.originZ],p=ey(t,s,r,a,M),f=ql(this.length,s,r),x=this.tmpOrigin.fromArray(M).add(l);for(const A of v){const y=py.includes(A)?x:u,R=this.tmpVec.fromArray(p[A]).multiplyScalar(f[A]);this.setArrow(this.arrows[A],i[A],y,R)}}setArrow(t,e,i,s){const r=s.length();if(t.visible=e&&r>1e-6*this.length,!t.visible)return;t.position.copy(i),t.setDirection(s.divideScalar(r));const a=Math.min(.25*r,.08*this.length);t.setLength(r,a,.5*a)}updateTrail(t,e){const i=Math.min(t.end-t.start,da),s=this.trail.geometry;if(i<=0){s.setDrawRange(0,0);return}const r=t.end-i,a=this.trailPositions,o=i+1;for(let l=0;l<o;l++){const h=l<i?t.frames[r+l]:e;a[3*l]=h.x[0]+h.pivot[0],a[3*l+1]=h.x[1]+h.pivot[1],a[3*l+2]=h.x[2]+h.pivot[2]}s.setDrawRange(0,o);const c=s.getAttribute("position");if(c.clearUpdateRanges(),c.addUpdateRange(0,3*o),c.needsUpdate=!0,o!==this.trailColored){this.trailColored=o;const l=this.trailColors,h=new le;for(let u=0;u<o;u++)h.copy(Pd).lerp(my,(u+1)/o),l[3*u]=h.r,l[3*u+1]=h.g,l[3*u+2]=h.b;const d=s.getAttribute("color");d.clearUpdateRanges(),d.addUpdateRange(0,3*o),d.needsUpdate=!0}}draw(t){const e=this.controls.update();return!t&&!e&&!this.invalid?!1:(this.invalid=!1,this.render(),!0)}render(){const t=this.camera.position.distanceTo(this.controls.target);this.stereo==="anaglyph"&&this.anaglyph!==null?(this.anaglyph.planeDistance=t,this.anaglyph.eyeSep=t/30,this.anaglyph.render(this.scene,this.camera)):this.stereo==="side by side"&&this.sideBySide!==null?(this.camera.focus=t,this.sideBySide.setEyeSeparation(t/30),this.sideBySide.render(this.scene,this.camera)):this.renderer.render(this.scene,this.camera)}screenshot(){return this.render(),this.renderer.domElement.toDataURL("image/png")}}const Ey={velocity:["velocity v","v [m/s], drawn as 0.25 s of travel"],momentum:["momentum m v","m v [kg m/s], 0.25 m per kg m/s"],gravity:["gravity m g","the weight m g d [N] (d: the gravity direction); forces: m·max(|g|, 1) N ↔ 0.5 l"],tension:["rod force (tension)","the rod force −T x/|x| [N], T from the server"],net:["net force m a","m a [N]: a = ẍ computed by the server’s core (relative to the pivot)"],angularMomentum:["angular momentum L","L = (x − o) × m v [kg m²/s] about the origin o, drawn from o"],torque:["torque τ","τ = (x − o) × m a [N m] about the origin o, drawn from o; dL/dt = τ"]};function by(n,t,e,i){const s=n.addFolder("View");s.add(t,"trail").onChange(e),s.add(t,"trailSeconds",1,120,1).name("trail [s]").onChange(e),s.add(t,"sphere").name("sphere of reach").onChange(e),s.add(t,"axes").onChange(e);const r={topView:!1};s.add(r,"topView").name("top view").onChange(o=>{i(o),e()}),s.add(t,"stereo",[...uy]).name("stereo").onChange(e).domElement.title="anaglyph: red–cyan glasses; side by side: a stereo viewer (three.js AnaglyphEffect / StereoEffect)",s.close();const a=n.addFolder("Vectors");for(const[o,[c,l]]of Object.entries(Ey)){const h=a.add(t,o).name(c).onChange(e);h.domElement.title=l,h.domElement.dataset.vector=o}for(const o of["X","Y","Z"]){const c=`origin${o}`;a.add(t,c,-5,5,.01).name(`origin ${o.toLowerCase()} [m]`).onChange(e).domElement.title="origin of L and τ relative to the pivot (0: the pivot)"}return a.close(),s}class wy{constructor(t,e,i,s,r){this.view=s,this.gui=new uh({container:t,title:"Pendulab lab",width:270});const a={};this.model=a;const o=this.gui.addFolder("Pendulum"),c=dh((E,g)=>{r.send({type:"set_params",[E]:g})},50);for(const E of e.model.params){const g=T=>c(E.name,T);this.synced.push(bf(o,a,E,g,r.explain))}this.modelControls=new tg(o,e,r);const l=this.gui.addFolder("Integrator"),h={};for(const E of e.methods){const g=[`order ${E.order}`,E.symplectic?"symplectic":"",E.adaptive?"adaptive":""].filter(Boolean).join(", ");h[`${E.name} (${g})`]=E.name}a.method=e.methods.find(E=>E.default)?.name??e.methods[0]?.name??"rattle";const d=l.add(a,"method",h).onChange(E=>r.send({type:"set_method",method:E}));d.domElement.title=e.methods.map(E=>`${E.name}: ${E.summary}`).join(`
`),this.synced.push(d);const u=e.controls.dt;a.dt=u.default??.001;const m=l.add(a,"dt").name("dt [s]").decimals(6).onFinishChange(E=>{if(!(E>=u.min&&E<=u.max)){r.explain(`dt must be between ${u.min} and ${u.max} s`);return}r.send({type:"set_method",dt:E})});m.domElement.title=`${u.description}; ${u.min} … ${u.max} s (dop853 chooses its own)`,this.synced.push(m);const v=this.gui.addFolder("Run"),M=e.controls.time_scale;a.time_scale=M.default??1;const p=v.add(a,"time_scale").name("time scale [×]").decimals(3).onFinishChange(E=>{if(!(E>=M.min&&E<=M.max)){r.explain(`the time scale must be between ${M.min} and ${M.max}`);return}r.send({type:"set_time_scale",time_scale:E})});p.domElement.title=`${M.description}; ${M.min} … ${M.max}`,this.synced.push(p),a.paused=!1,a.run=()=>r.send({type:a.paused===!0?"resume":"pause"}),this.runButton=v.add(a,"run").name("pause"),a.stepN=1;const f=e.controls.step_n;v.add(a,"stepN",f.min,Math.min(f.max,1e3),1).name("steps per step"),a.step=()=>r.send({type:"step",n:Math.round(Number(a.stepN))}),v.add(a,"step").name("step"),a.reset=()=>r.send({type:"reset"}),v.add(a,"reset").name("reset to start");const x={};for(const E of i)E.error===void 0&&(x[E.title?`${E.name}: ${E.title}`:E.name]=E.name);a.scenario="";const A=v.add(a,"scenario",x).name("scenario").onChange(E=>r.send({type:"load_scenario",name:E}));this.synced.push(A),by(this.gui,s,()=>r.viewChanged(this.view,this.topView),E=>{this.topView=E});const y=this.gui.addFolder("Share and export").close();a.csv=()=>r.downloadCSV(),y.add(a,"csv").name("download trajectory (CSV)"),a.toml=()=>r.downloadTOML();const R=y.add(a,"toml").name("download scenario (TOML)");R.domElement.dataset.control="toml",R.domElement.title="the scenario as it stands (model, parameters, start, method) as a file for `pendulab run`",a.png=()=>r.screenshot(),y.add(a,"png").name("screenshot (PNG)"),a.link=()=>r.copyLink(),y.add(a,"link").name("copy link to this scenario")}view;gui;model;synced=[];runButton;modelControls;topView=!1;sync(t){const e=this.model;e.length=t.params.length,e.mass=t.params.mass,e.g=t.params.g,e.method=t.method,e.dt=t.dt,e.time_scale=t.time_scale,e.paused=t.paused,e.scenario=t.scenario??"";for(const i of this.synced)i.domElement.contains(document.activeElement)||i.updateDisplay();this.runButton.name(t.paused?"start":"pause"),this.modelControls.sync(t)}}const Ty=!0,gn="u-",Ay="uplot",Ry=gn+"hz",Cy=gn+"vt",Py=gn+"title",Ly=gn+"wrap",Dy=gn+"under",Ny=gn+"over",Iy=gn+"axis",Hs=gn+"off",Uy=gn+"select",Fy=gn+"cursor-x",Oy=gn+"cursor-y",By=gn+"cursor-pt",zy=gn+"legend",ky=gn+"live",Hy=gn+"inline",Gy=gn+"series",Vy=gn+"marker",Dd=gn+"label",Wy=gn+"value",oa="width",la="height",na="top",Nd="bottom",_r="left",Kl="right",Ch="#000",Id=Ch+"0",Zl="mousemove",Ud="mousedown",Jl="mouseup",Fd="mouseenter",Od="mouseleave",Bd="dblclick",Xy="resize",$y="scroll",zd="change",Io="dppxchange",Ph="--",Fr=typeof window<"u",Qc=Fr?document:null,wr=Fr?window:null,Yy=Fr?navigator:null;let Me,ho;function jc(){let n=devicePixelRatio;Me!=n&&(Me=n,ho&&eh(zd,ho,jc),ho=matchMedia(`(min-resolution: ${Me-.001}dppx) and (max-resolution: ${Me+.001}dppx)`),Vs(zd,ho,jc),wr.dispatchEvent(new CustomEvent(Io)))}function Zn(n,t){if(t!=null){let e=n.classList;!e.contains(t)&&e.add(t)}}function th(n,t){let e=n.classList;e.contains(t)&&e.remove(t)}function ke(n,t,e){n.style[t]=e+"px"}function vi(n,t,e,i){let s=Qc.createElement(n);return t!=null&&Zn(s,t),e?.insertBefore(s,i),s}function ri(n,t){return vi("div",n,t)}const kd=new WeakMap;function Ui(n,t,e,i,s){let r="translate("+t+"px,"+e+"px)",a=kd.get(n);r!=a&&(n.style.transform=r,kd.set(n,r),t<0||e<0||t>i||e>s?Zn(n,Hs):th(n,Hs))}const Hd=new WeakMap;function Gd(n,t,e){let i=t+e,s=Hd.get(n);i!=s&&(Hd.set(n,i),n.style.background=t,n.style.borderColor=e)}const Vd=new WeakMap;function Wd(n,t,e,i){let s=t+""+e,r=Vd.get(n);s!=r&&(Vd.set(n,s),n.style.height=e+"px",n.style.width=t+"px",n.style.marginLeft=i?-t/2+"px":0,n.style.marginTop=i?-e/2+"px":0)}const Lh={passive:!0},qy={...Lh,capture:!0};function Vs(n,t,e,i){t.addEventListener(n,e,i?qy:Lh)}function eh(n,t,e,i){t.removeEventListener(n,e,Lh)}Fr&&jc();function xi(n,t,e,i){let s;e=e||0,i=i||t.length-1;let r=i<=2147483647;for(;i-e>1;)s=r?e+i>>1:Qn((e+i)/2),t[s]<n?e=s:i=s;return n-t[e]<=t[i]-n?e:i}function yp(n){return(e,i,s)=>{let r=-1,a=-1;for(let o=i;o<=s;o++)if(n(e[o])){r=o;break}for(let o=s;o>=i;o--)if(n(e[o])){a=o;break}return[r,a]}}const Ep=n=>n!=null,bp=n=>n!=null&&n>0,Go=yp(Ep),Ky=yp(bp);function Zy(n,t,e,i=0,s=!1){let r=s?Ky:Go,a=s?bp:Ep;[t,e]=r(n,t,e);let o=n[t],c=n[t];if(t>-1)if(i==1)o=n[t],c=n[e];else if(i==-1)o=n[e],c=n[t];else for(let l=t;l<=e;l++){let h=n[l];a(h)&&(h<o?o=h:h>c&&(c=h))}return[o??Ne,c??-Ne]}function Vo(n,t,e,i){let s=Yd(n),r=Yd(t);n==t&&(s==-1?(n*=e,t/=e):(n/=e,t*=e));let a=e==10?is:wp,o=s==1?Qn:oi,c=r==1?oi:Qn,l=o(a(fn(n))),h=c(a(fn(t))),d=Pr(e,l),u=Pr(e,h);return e==10&&(l<0&&(d=Ie(d,-l)),h<0&&(u=Ie(u,-h))),i||e==2?(n=d*s,t=u*r):(n=Cp(n,d),t=Wo(t,u)),[n,t]}function Dh(n,t,e,i){let s=Vo(n,t,e,i);return n==0&&(s[0]=0),t==0&&(s[1]=0),s}const Nh=.1,Xd={mode:3,pad:Nh},fa={pad:0,soft:null,mode:0},Jy={min:fa,max:fa};function Uo(n,t,e,i){return Xo(e)?$d(n,t,e):(fa.pad=e,fa.soft=i?0:null,fa.mode=i?3:0,$d(n,t,Jy))}function xe(n,t){return n??t}function Qy(n,t,e){for(t=xe(t,0),e=xe(e,n.length-1);t<=e;){if(n[t]!=null)return!0;t++}return!1}function $d(n,t,e){let i=e.min,s=e.max,r=xe(i.pad,0),a=xe(s.pad,0),o=xe(i.hard,-Ne),c=xe(s.hard,Ne),l=xe(i.soft,Ne),h=xe(s.soft,-Ne),d=xe(i.mode,0),u=xe(s.mode,0),m=t-n,v=is(m),M=kn(fn(n),fn(t)),p=is(M),f=fn(p-v);(m<1e-24||f>10)&&(m=0,(n==0||t==0)&&(m=1e-24,d==2&&l!=Ne&&(r=0),u==2&&h!=-Ne&&(a=0)));let x=m||M||1e3,A=is(x),y=Pr(10,Qn(A)),R=x*(m==0?n==0?.1:1:r),E=Ie(Cp(n-R,y/10),24),g=n>=l&&(d==1||d==3&&E<=l||d==2&&E>=l)?l:Ne,T=kn(o,E<g&&n>=g?g:yi(g,E)),z=x*(m==0?t==0?.1:1:a),U=Ie(Wo(t+z,y/10),24),D=t<=h&&(u==1||u==3&&U>=h||u==2&&U<=h)?h:-Ne,I=yi(c,U>D&&t<=D?D:kn(D,U));return T==I&&T==0&&(I=100),[T,I]}const jy=new Intl.NumberFormat(Fr?Yy.language:"en-US"),Ih=n=>jy.format(n),jn=Math,bo=jn.PI,fn=jn.abs,Qn=jn.floor,dn=jn.round,oi=jn.ceil,yi=jn.min,kn=jn.max,Pr=jn.pow,Yd=jn.sign,is=jn.log10,wp=jn.log2,tE=(n,t=1)=>jn.sinh(n)*t,Ql=(n,t=1)=>jn.asinh(n/t),Ne=1/0;function qd(n){return(is((n^n>>31)-(n>>31))|0)+1}function nh(n,t,e){return yi(kn(n,t),e)}function Tp(n){return typeof n=="function"}function pe(n){return Tp(n)?n:()=>n}const eE=()=>{},Ap=n=>n,Rp=(n,t)=>t,nE=n=>null,Kd=n=>!0,Zd=(n,t)=>n==t,iE=/\.\d*?(?=9{6,}|0{6,})/gm,$s=n=>{if(Lp(n)||Rs.has(n))return n;const t=`${n}`,e=t.match(iE);if(e==null)return n;let i=e[0].length-1;if(t.indexOf("e-")!=-1){let[s,r]=t.split("e");return+`${$s(s)}e${r}`}return Ie(n,i)};function zs(n,t){return $s(Ie($s(n/t))*t)}function Wo(n,t){return $s(oi($s(n/t))*t)}function Cp(n,t){return $s(Qn($s(n/t))*t)}function Ie(n,t=0){if(Lp(n))return n;let e=10**t,i=n*e*(1+Number.EPSILON);return dn(i)/e}const Rs=new Map;function Pp(n){return((""+n).split(".")[1]||"").length}function Ea(n,t,e,i){let s=[],r=i.map(Pp);for(let a=t;a<e;a++){let o=fn(a),c=Ie(Pr(n,a),o);for(let l=0;l<i.length;l++){let h=n==10?+`${i[l]}e${a}`:i[l]*c,d=(a>=0?0:o)+(a>=r[l]?0:r[l]),u=n==10?h:Ie(h,d);s.push(u),Rs.set(u,d)}}return s}const pa={},Uh=[],Lr=[null,null],vs=Array.isArray,Lp=Number.isInteger,sE=n=>n===void 0;function Jd(n){return typeof n=="string"}function Xo(n){let t=!1;if(n!=null){let e=n.constructor;t=e==null||e==Object}return t}function rE(n){return n!=null&&typeof n=="object"}const aE=Object.getPrototypeOf(Uint8Array),Dp="__proto__";function Dr(n,t=Xo){let e;if(vs(n)){let i=n.find(s=>s!=null);if(vs(i)||t(i)){e=Array(n.length);for(let s=0;s<n.length;s++)e[s]=Dr(n[s],t)}else e=n.slice()}else if(n instanceof aE)e=n.slice();else if(t(n)){e={};for(let i in n)i!=Dp&&(e[i]=Dr(n[i],t))}else e=n;return e}function on(n){let t=arguments;for(let e=1;e<t.length;e++){let i=t[e];for(let s in i)s!=Dp&&(Xo(n[s])?on(n[s],Dr(i[s])):n[s]=Dr(i[s]))}return n}const oE=0,lE=1,cE=2;function hE(n,t,e){for(let i=0,s,r=-1;i<t.length;i++){let a=t[i];if(a>r){for(s=a-1;s>=0&&n[s]==null;)n[s--]=null;for(s=a+1;s<e&&n[s]==null;)n[r=s++]=null}}}function uE(n,t){if(pE(n)){let a=n[0].slice();for(let o=1;o<n.length;o++)a.push(...n[o].slice(1));return mE(a[0])||(a=fE(a)),a}let e=new Set;for(let a=0;a<n.length;a++){let c=n[a][0],l=c.length;for(let h=0;h<l;h++)e.add(c[h])}let i=[Array.from(e).sort((a,o)=>a-o)],s=i[0].length,r=new Map;for(let a=0;a<s;a++)r.set(i[0][a],a);for(let a=0;a<n.length;a++){let o=n[a],c=o[0];for(let l=1;l<o.length;l++){let h=o[l],d=Array(s).fill(void 0),u=t?t[a][l]:lE,m=[];for(let v=0;v<h.length;v++){let M=h[v],p=r.get(c[v]);M===null?u!=oE&&(d[p]=M,u==cE&&m.push(p)):d[p]=M}hE(d,m,s),i.push(d)}}return i}const dE=typeof queueMicrotask>"u"?n=>Promise.resolve().then(n):queueMicrotask;function fE(n){let t=n[0],e=t.length,i=Array(e);for(let r=0;r<i.length;r++)i[r]=r;i.sort((r,a)=>t[r]-t[a]);let s=[];for(let r=0;r<n.length;r++){let a=n[r],o=Array(e);for(let c=0;c<e;c++)o[c]=a[i[c]];s.push(o)}return s}function pE(n){let t=n[0][0],e=t.length;for(let i=1;i<n.length;i++){let s=n[i][0];if(s.length!=e)return!1;if(s!=t){for(let r=0;r<e;r++)if(s[r]!=t[r])return!1}}return!0}function mE(n,t=100){const e=n.length;if(e<=1)return!0;let i=0,s=e-1;for(;i<=s&&n[i]==null;)i++;for(;s>=i&&n[s]==null;)s--;if(s<=i)return!0;const r=kn(1,Qn((s-i+1)/t));for(let a=n[i],o=i+r;o<=s;o+=r){const c=n[o];if(c!=null){if(c<=a)return!1;a=c}}return!0}const Np=["January","February","March","April","May","June","July","August","September","October","November","December"],Ip=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function Up(n){return n.slice(0,3)}const gE=Ip.map(Up),_E=Np.map(Up),vE={MMMM:Np,MMM:_E,WWWW:Ip,WWW:gE};function ia(n){return(n<10?"0":"")+n}function xE(n){return(n<10?"00":n<100?"0":"")+n}const SE={YYYY:n=>n.getFullYear(),YY:n=>(n.getFullYear()+"").slice(2),MMMM:(n,t)=>t.MMMM[n.getMonth()],MMM:(n,t)=>t.MMM[n.getMonth()],MM:n=>ia(n.getMonth()+1),M:n=>n.getMonth()+1,DD:n=>ia(n.getDate()),D:n=>n.getDate(),WWWW:(n,t)=>t.WWWW[n.getDay()],WWW:(n,t)=>t.WWW[n.getDay()],HH:n=>ia(n.getHours()),H:n=>n.getHours(),h:n=>{let t=n.getHours();return t==0?12:t>12?t-12:t},AA:n=>n.getHours()>=12?"PM":"AM",aa:n=>n.getHours()>=12?"pm":"am",a:n=>n.getHours()>=12?"p":"a",mm:n=>ia(n.getMinutes()),m:n=>n.getMinutes(),ss:n=>ia(n.getSeconds()),s:n=>n.getSeconds(),fff:n=>xE(n.getMilliseconds())};function Fh(n,t){t=t||vE;let e=[],i=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=i.exec(n);)e.push(s[0][0]=="{"?SE[s[1]]:s[0]);return r=>{let a="";for(let o=0;o<e.length;o++)a+=typeof e[o]=="string"?e[o]:e[o](r,t);return a}}const ME=new Intl.DateTimeFormat().resolvedOptions().timeZone;function yE(n,t){let e;return t=="UTC"||t=="Etc/UTC"?e=new Date(+n+n.getTimezoneOffset()*6e4):t==ME?e=n:(e=new Date(n.toLocaleString("en-US",{timeZone:t})),e.setMilliseconds(n.getMilliseconds())),e}const Fp=n=>n%1==0,Fo=[1,2,2.5,5],EE=Ea(10,-32,0,Fo),Op=Ea(10,0,32,Fo),bE=Op.filter(Fp),ks=EE.concat(Op),Oh=`
`,Bp="{YYYY}",Qd=Oh+Bp,zp="{M}/{D}",ca=Oh+zp,uo=ca+"/{YY}",kp="{aa}",wE="{h}:{mm}",xr=wE+kp,jd=Oh+xr,tf=":{ss}",Ee=null;function Hp(n){let t=n*1e3,e=t*60,i=e*60,s=i*24,r=s*30,a=s*365,c=(n==1?Ea(10,0,3,Fo).filter(Fp):Ea(10,-3,0,Fo)).concat([t,t*5,t*10,t*15,t*30,e,e*5,e*10,e*15,e*30,i,i*2,i*3,i*4,i*6,i*8,i*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,a,a*2,a*5,a*10,a*25,a*50,a*100]);const l=[[a,Bp,Ee,Ee,Ee,Ee,Ee,Ee,1],[s*28,"{MMM}",Qd,Ee,Ee,Ee,Ee,Ee,1],[s,zp,Qd,Ee,Ee,Ee,Ee,Ee,1],[i,"{h}"+kp,uo,Ee,ca,Ee,Ee,Ee,1],[e,xr,uo,Ee,ca,Ee,Ee,Ee,1],[t,tf,uo+" "+xr,Ee,ca+" "+xr,Ee,jd,Ee,1],[n,tf+".{fff}",uo+" "+xr,Ee,ca+" "+xr,Ee,jd,Ee,1]];function h(d){return(u,m,v,M,p,f)=>{let x=[],A=p>=a,y=p>=r&&p<a,R=d(v),E=Ie(R*n,3),g=jl(R.getFullYear(),A?0:R.getMonth(),y||A?1:R.getDate()),T=Ie(g*n,3);if(y||A){let z=y?p/r:0,U=A?p/a:0,D=E==T?E:Ie(jl(g.getFullYear()+U,g.getMonth()+z,1)*n,3),I=new Date(dn(D/n)),B=I.getFullYear(),L=I.getMonth();for(let G=0;D<=M;G++){let Y=jl(B+U*G,L+z*G,1),k=Y-d(Ie(Y*n,3));D=Ie((+Y+k)*n,3),D<=M&&x.push(D)}}else{let z=p>=s?s:p,U=Qn(v)-Qn(E),D=T+U+Wo(E-T,z);x.push(D);let I=d(D),B=I.getHours()+I.getMinutes()/e+I.getSeconds()/i,L=p/i,G=u.axes[m]._space,Y=f/G;for(;D=Ie(D+p,n==1?0:3),!(D>M);)if(L>1){let k=Qn(Ie(B+L,6))%24,Q=d(D).getHours()-k;Q>1&&(Q=-1),D-=Q*i,B=(B+L)%24;let nt=x[x.length-1];Ie((D-nt)/p,3)*Y>=.7&&x.push(D)}else x.push(D)}return x}}return[c,l,h]}const[TE,AE,RE]=Hp(1),[CE,PE,LE]=Hp(.001);Ea(2,-53,53,[1]);function ef(n,t){return n.map(e=>e.map((i,s)=>s==0||s==8||i==null?i:t(s==1||e[8]==0?i:e[1]+i)))}function nf(n,t){return(e,i,s,r,a)=>{let o=t.find(v=>a>=v[0])||t[t.length-1],c,l,h,d,u,m;return i.map(v=>{let M=n(v),p=M.getFullYear(),f=M.getMonth(),x=M.getDate(),A=M.getHours(),y=M.getMinutes(),R=M.getSeconds(),E=p!=c&&o[2]||f!=l&&o[3]||x!=h&&o[4]||A!=d&&o[5]||y!=u&&o[6]||R!=m&&o[7]||o[1];return c=p,l=f,h=x,d=A,u=y,m=R,E(M)})}}function DE(n,t){let e=Fh(t);return(i,s,r,a,o)=>s.map(c=>e(n(c)))}function jl(n,t,e){return new Date(n,t,e)}function sf(n,t){return t(n)}const NE="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function rf(n,t){return(e,i,s,r)=>r==null?Ph:t(n(i))}function IE(n,t){let e=n.series[t];return e.width?e.stroke(n,t):e.points.width?e.points.stroke(n,t):null}function UE(n,t){return n.series[t].fill(n,t)}const FE={show:!0,live:!0,isolate:!1,mount:eE,markers:{show:!0,width:2,stroke:IE,fill:UE,dash:"solid"},idx:null,idxs:null,values:[]};function OE(n,t){let e=n.cursor.points,i=ri(),s=e.size(n,t);ke(i,oa,s),ke(i,la,s);let r=s/-2;ke(i,"marginLeft",r),ke(i,"marginTop",r);let a=e.width(n,t,s);return a&&ke(i,"borderWidth",a),i}function BE(n,t){let e=n.series[t].points;return e._fill||e._stroke}function zE(n,t){let e=n.series[t].points;return e._stroke||e._fill}function kE(n,t){return n.series[t].points.size}const tc=[0,0];function HE(n,t,e){return tc[0]=t,tc[1]=e,tc}function fo(n,t,e,i=!0){return s=>{s.button==0&&(!i||s.target==t)&&e(s)}}function ec(n,t,e,i=!0){return s=>{(!i||s.target==t)&&e(s)}}const GE={show:!0,x:!0,y:!0,lock:!1,move:HE,points:{one:!1,show:OE,size:kE,width:0,stroke:zE,fill:BE},bind:{mousedown:fo,mouseup:fo,click:fo,dblclick:fo,mousemove:ec,mouseleave:ec,mouseenter:ec},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(n,t)=>{t.stopPropagation(),t.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(n,t,e,i,s)=>i-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},Gp={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},Bh=on({},Gp,{filter:Rp}),Vp=on({},Bh,{size:10}),Wp=on({},Gp,{show:!1}),zh='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',Xp="bold "+zh,$p=1.5,af={show:!0,scale:"x",stroke:Ch,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Xp,side:2,grid:Bh,ticks:Vp,border:Wp,font:zh,lineGap:$p,rotate:0},VE="Value",WE="Time",of={show:!0,scale:"x",auto:!1,sorted:1,min:Ne,max:-Ne,idxs:[]};function XE(n,t,e,i,s){return t.map(r=>r==null?"":Ih(r))}function $E(n,t,e,i,s,r,a){let o=[],c=Rs.get(s)||0;e=a?e:Ie(Wo(e,s),c);for(let l=e;l<=i;l=Ie(l+s,c))o.push(Object.is(l,-0)?0:l);return o}function ih(n,t,e,i,s,r,a){const o=[],c=n.scales[n.axes[t].scale].log,l=c==10?is:wp,h=Qn(l(e));s=Pr(c,h),c==10&&(s=ks[xi(s,ks)]);let d=e,u=s*c;c==10&&(u=ks[xi(u,ks)]);do o.push(d),d=d+s,c==10&&!Rs.has(d)&&(d=Ie(d,Rs.get(s))),d>=u&&(s=d,u=s*c,c==10&&(u=ks[xi(u,ks)]));while(d<=i);return o}function YE(n,t,e,i,s,r,a){let c=n.scales[n.axes[t].scale].asinh,l=i>c?ih(n,t,kn(c,e),i,s):[c],h=i>=0&&e<=0?[0]:[];return(e<-c?ih(n,t,kn(c,-i),-e,s):[c]).reverse().map(u=>-u).concat(h,l)}const Yp=/./,qE=/[12357]/,KE=/[125]/,lf=/1/,sh=(n,t,e,i)=>n.map((s,r)=>t==4&&s==0||r%i==0&&e.test(s.toExponential()[s<0?1:0])?s:null);function ZE(n,t,e,i,s){let r=n.axes[e],a=r.scale,o=n.scales[a],c=n.valToPos,l=r._space,h=c(10,a),d=c(9,a)-h>=l?Yp:c(7,a)-h>=l?qE:c(5,a)-h>=l?KE:lf;if(d==lf){let u=fn(c(1,a)-h);if(u<l)return sh(t.slice().reverse(),o.distr,d,oi(l/u)).reverse()}return sh(t,o.distr,d,1)}function JE(n,t,e,i,s){let r=n.axes[e],a=r.scale,o=r._space,c=n.valToPos,l=fn(c(1,a)-c(2,a));return l<o?sh(t.slice().reverse(),3,Yp,oi(o/l)).reverse():t}function QE(n,t,e,i){return i==null?Ph:t==null?"":Ih(t)}const cf={show:!0,scale:"y",stroke:Ch,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Xp,side:3,grid:Bh,ticks:Vp,border:Wp,font:zh,lineGap:$p,rotate:0};function jE(n,t){let e=3+(n||1)*2;return Ie(e*t,3)}function tb(n,t){let{scale:e,idxs:i}=n.series[0],s=n._data[0],r=n.valToPos(s[i[0]],e,!0),a=n.valToPos(s[i[1]],e,!0),o=fn(a-r),c=n.series[t],l=o/(c.points.space*Me);return i[1]-i[0]<=l}const hf={scale:null,auto:!0,sorted:0,min:Ne,max:-Ne},qp=(n,t,e,i,s)=>s,uf={show:!0,auto:!0,sorted:0,gaps:qp,alpha:1,facets:[on({},hf,{scale:"x"}),on({},hf,{scale:"y"})]},df={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:qp,alpha:1,points:{show:tb,filter:null},values:null,min:Ne,max:-Ne,idxs:[],path:null,clip:null};function eb(n,t,e,i,s){return e/10}const Kp={time:Ty,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},nb=on({},Kp,{time:!1,ori:1}),ff={};function Zp(n,t){let e=ff[n];return e||(e={key:n,plots:[],sub(i){e.plots.push(i)},unsub(i){e.plots=e.plots.filter(s=>s!=i)},pub(i,s,r,a,o,c,l){for(let h=0;h<e.plots.length;h++)e.plots[h]!=s&&e.plots[h].pub(i,s,r,a,o,c,l)}},n!=null&&(ff[n]=e)),e}const Nr=1,rh=2;function Ys(n,t,e){const i=n.mode,s=n.series[t],r=i==2?n._data[t]:n._data,a=n.scales,o=n.bbox;let c=r[0],l=i==2?r[1]:r[t],h=i==2?a[s.facets[0].scale]:a[n.series[0].scale],d=i==2?a[s.facets[1].scale]:a[s.scale],u=o.left,m=o.top,v=o.width,M=o.height,p=n.valToPosH,f=n.valToPosV;return h.ori==0?e(s,c,l,h,d,p,f,u,m,v,M,Yo,Or,Ko,Qp,tm):e(s,c,l,h,d,f,p,m,u,M,v,qo,Br,Gh,jp,em)}function kh(n,t){let e=0,i=0,s=xe(n.bands,Uh);for(let r=0;r<s.length;r++){let a=s[r];a.series[0]==t?e=a.dir:a.series[1]==t&&(a.dir==1?i|=1:i|=2)}return[e,i==1?-1:i==2?1:i==3?2:0]}function ib(n,t,e,i,s){let r=n.mode,a=n.series[t],o=r==2?a.facets[1].scale:a.scale,c=n.scales[o];return s==-1?c.min:s==1?c.max:c.distr==3?c.dir==1?c.min:c.max:0}function ss(n,t,e,i,s,r){return Ys(n,t,(a,o,c,l,h,d,u,m,v,M,p)=>{let f=a.pxRound;const x=l.dir*(l.ori==0?1:-1),A=l.ori==0?Or:Br;let y,R;x==1?(y=e,R=i):(y=i,R=e);let E=f(d(o[y],l,M,m)),g=f(u(c[y],h,p,v)),T=f(d(o[R],l,M,m)),z=f(u(r==1?h.max:h.min,h,p,v)),U=new Path2D(s);return A(U,T,z),A(U,E,z),A(U,E,g),U})}function $o(n,t,e,i,s,r){let a=null;if(n.length>0){a=new Path2D;const o=t==0?Ko:Gh;let c=e;for(let d=0;d<n.length;d++){let u=n[d];if(u[1]>u[0]){let m=u[0]-c;m>0&&o(a,c,i,m,i+r),c=u[1]}}let l=e+s-c,h=10;l>0&&o(a,c,i-h/2,l,i+r+h)}return a}function sb(n,t,e){let i=n[n.length-1];i&&i[0]==t?i[1]=e:n.push([t,e])}function Hh(n,t,e,i,s,r,a){let o=[],c=n.length;for(let l=s==1?e:i;l>=e&&l<=i;l+=s)if(t[l]===null){let d=l,u=l;if(s==1)for(;++l<=i&&t[l]===null;)u=l;else for(;--l>=e&&t[l]===null;)u=l;let m=r(n[d]),v=u==d?m:r(n[u]),M=d-s;m=a<=0&&M>=0&&M<c?r(n[M]):m;let f=u+s;v=a>=0&&f>=0&&f<c?r(n[f]):v,v>=m&&o.push([m,v])}return o}function pf(n){return n==0?Ap:n==1?dn:t=>zs(t,n)}function Jp(n){let t=n==0?Yo:qo,e=n==0?(s,r,a,o,c,l)=>{s.arcTo(r,a,o,c,l)}:(s,r,a,o,c,l)=>{s.arcTo(a,r,c,o,l)},i=n==0?(s,r,a,o,c)=>{s.rect(r,a,o,c)}:(s,r,a,o,c)=>{s.rect(a,r,c,o)};return(s,r,a,o,c,l=0,h=0)=>{l==0&&h==0?i(s,r,a,o,c):(l=yi(l,o/2,c/2),h=yi(h,o/2,c/2),t(s,r+l,a),e(s,r+o,a,r+o,a+c,l),e(s,r+o,a+c,r,a+c,h),e(s,r,a+c,r,a,h),e(s,r,a,r+o,a,l),s.closePath())}}const Yo=(n,t,e)=>{n.moveTo(t,e)},qo=(n,t,e)=>{n.moveTo(e,t)},Or=(n,t,e)=>{n.lineTo(t,e)},Br=(n,t,e)=>{n.lineTo(e,t)},Ko=Jp(0),Gh=Jp(1),Qp=(n,t,e,i,s,r)=>{n.arc(t,e,i,s,r)},jp=(n,t,e,i,s,r)=>{n.arc(e,t,i,s,r)},tm=(n,t,e,i,s,r,a)=>{n.bezierCurveTo(t,e,i,s,r,a)},em=(n,t,e,i,s,r,a)=>{n.bezierCurveTo(e,t,s,i,a,r)};function nm(n){return(t,e,i,s,r)=>Ys(t,e,(a,o,c,l,h,d,u,m,v,M,p)=>{let{pxRound:f,points:x}=a,A,y;l.ori==0?(A=Yo,y=Qp):(A=qo,y=jp);const R=Ie(x.width*Me,3);let E=(x.size-x.width)/2*Me,g=Ie(E*2,3),T=new Path2D,z=new Path2D,{left:U,top:D,width:I,height:B}=t.bbox;Ko(z,U-g,D-g,I+g*2,B+g*2);const L=G=>{if(c[G]!=null){let Y=f(d(o[G],l,M,m)),k=f(u(c[G],h,p,v));A(T,Y+E,k),y(T,Y,k,E,0,bo*2)}};if(r)r.forEach(L);else for(let G=i;G<=s;G++)L(G);return{stroke:R>0?T:null,fill:T,clip:z,flags:Nr|rh}})}function im(n){return(t,e,i,s,r,a)=>{i!=s&&(r!=i&&a!=i&&n(t,e,i),r!=s&&a!=s&&n(t,e,s),n(t,e,a))}}const rb=im(Or),ab=im(Br);function sm(n){const t=xe(n?.alignGaps,0);return(e,i,s,r)=>Ys(e,i,(a,o,c,l,h,d,u,m,v,M,p)=>{[s,r]=Go(c,s,r);let f=a.pxRound,x=B=>f(d(B,l,M,m)),A=B=>f(u(B,h,p,v)),y,R;l.ori==0?(y=Or,R=rb):(y=Br,R=ab);const E=l.dir*(l.ori==0?1:-1),g={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:Nr},T=g.stroke;let z=!1;if(r-s>=M*4){let B=ot=>e.posToVal(ot,l.key,!0),L=null,G=null,Y,k,lt,K=x(o[E==1?s:r]),Q=x(o[s]),nt=x(o[r]),ut=B(E==1?Q+1:nt-1);for(let ot=E==1?s:r;ot>=s&&ot<=r;ot+=E){let j=o[ot],_t=(E==1?j<ut:j>ut)?K:x(j),Tt=c[ot];_t==K?Tt!=null?(k=Tt,L==null?(y(T,_t,A(k)),Y=L=G=k):k<L?L=k:k>G&&(G=k)):Tt===null&&(z=!0):(L!=null&&R(T,K,A(L),A(G),A(Y),A(k)),Tt!=null?(k=Tt,y(T,_t,A(k)),L=G=Y=k):(L=G=null,Tt===null&&(z=!0)),K=_t,ut=B(K+E))}L!=null&&L!=G&&lt!=K&&R(T,K,A(L),A(G),A(Y),A(k))}else for(let B=E==1?s:r;B>=s&&B<=r;B+=E){let L=c[B];L===null?z=!0:L!=null&&y(T,x(o[B]),A(L))}let[D,I]=kh(e,i);if(a.fill!=null||D!=0){let B=g.fill=new Path2D(T),L=a.fillTo(e,i,a.min,a.max,D),G=A(L),Y=x(o[s]),k=x(o[r]);E==-1&&([k,Y]=[Y,k]),y(B,k,G),y(B,Y,G)}if(!a.spanGaps){let B=[];z&&B.push(...Hh(o,c,s,r,E,x,t)),g.gaps=B=a.gaps(e,i,s,r,B),g.clip=$o(B,l.ori,m,v,M,p)}return I!=0&&(g.band=I==2?[ss(e,i,s,r,T,-1),ss(e,i,s,r,T,1)]:ss(e,i,s,r,T,I)),g})}function ob(n){const t=xe(n.align,1),e=xe(n.ascDesc,!1),i=xe(n.alignGaps,0),s=xe(n.extend,!1);return(r,a,o,c)=>Ys(r,a,(l,h,d,u,m,v,M,p,f,x,A)=>{[o,c]=Go(d,o,c);let y=l.pxRound,{left:R,width:E}=r.bbox,g=Q=>y(v(Q,u,x,p)),T=Q=>y(M(Q,m,A,f)),z=u.ori==0?Or:Br;const U={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:Nr},D=U.stroke,I=u.dir*(u.ori==0?1:-1);let B=T(d[I==1?o:c]),L=g(h[I==1?o:c]),G=L,Y=L;s&&t==-1&&(Y=R,z(D,Y,B)),z(D,L,B);for(let Q=I==1?o:c;Q>=o&&Q<=c;Q+=I){let nt=d[Q];if(nt==null)continue;let ut=g(h[Q]),ot=T(nt);t==1?z(D,ut,B):z(D,G,ot),z(D,ut,ot),B=ot,G=ut}let k=G;s&&t==1&&(k=R+E,z(D,k,B));let[lt,K]=kh(r,a);if(l.fill!=null||lt!=0){let Q=U.fill=new Path2D(D),nt=l.fillTo(r,a,l.min,l.max,lt),ut=T(nt);z(Q,k,ut),z(Q,Y,ut)}if(!l.spanGaps){let Q=[];Q.push(...Hh(h,d,o,c,I,g,i));let nt=l.width*Me/2,ut=e||t==1?nt:-nt,ot=e||t==-1?-nt:nt;Q.forEach(j=>{j[0]+=ut,j[1]+=ot}),U.gaps=Q=l.gaps(r,a,o,c,Q),U.clip=$o(Q,u.ori,p,f,x,A)}return K!=0&&(U.band=K==2?[ss(r,a,o,c,D,-1),ss(r,a,o,c,D,1)]:ss(r,a,o,c,D,K)),U})}function mf(n,t,e,i,s,r,a=Ne){if(n.length>1){let o=null;for(let c=0,l=1/0;c<n.length;c++)if(t[c]!==void 0){if(o!=null){let h=fn(n[c]-n[o]);h<l&&(l=h,a=fn(e(n[c],i,s,r)-e(n[o],i,s,r)))}o=c}}return a}function lb(n){n=n||pa;const t=xe(n.size,[.6,Ne,1]),e=n.align||0,i=n.gap||0;let s=n.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;const r=pe(s),a=1-t[0],o=xe(t[1],Ne),c=xe(t[2],1),l=xe(n.disp,pa),h=xe(n.each,m=>{}),{fill:d,stroke:u}=l;return(m,v,M,p)=>Ys(m,v,(f,x,A,y,R,E,g,T,z,U,D)=>{let I=f.pxRound,B=e,L=i*Me,G=o*Me,Y=c*Me,k,lt;y.ori==0?[k,lt]=r(m,v):[lt,k]=r(m,v);const K=y.dir*(y.ori==0?1:-1);let Q=y.ori==0?Ko:Gh,nt=y.ori==0?h:(Rt,Xt,ne,yt,De,zt,Wt)=>{h(Rt,Xt,ne,De,yt,Wt,zt)},ut=xe(m.bands,Uh).find(Rt=>Rt.series[0]==v),ot=ut!=null?ut.dir:0,j=f.fillTo(m,v,f.min,f.max,ot),pt=I(g(j,R,D,z)),_t,Tt,Mt,Gt=U,ee=I(f.width*Me),kt=!1,oe=null,se=null,Qt=null,He=null;d!=null&&(ee==0||u!=null)&&(kt=!0,oe=d.values(m,v,M,p),se=new Map,new Set(oe).forEach(Rt=>{Rt!=null&&se.set(Rt,new Path2D)}),ee>0&&(Qt=u.values(m,v,M,p),He=new Map,new Set(Qt).forEach(Rt=>{Rt!=null&&He.set(Rt,new Path2D)})));let{x0:Ue,size:je}=l;if(Ue!=null&&je!=null){B=1,x=Ue.values(m,v,M,p),Ue.unit==2&&(x=x.map(ne=>m.posToVal(T+ne*U,y.key,!0)));let Rt=je.values(m,v,M,p);je.unit==2?Tt=Rt[0]*U:Tt=E(Rt[0],y,U,T)-E(0,y,U,T),Gt=mf(x,A,E,y,U,T,Gt),Mt=Gt-Tt+L}else Gt=mf(x,A,E,y,U,T,Gt),Mt=Gt*a+L,Tt=Gt-Mt;Mt<1&&(Mt=0),ee>=Tt/2&&(ee=0),Mt<5&&(I=Ap);let Re=Mt>0,_n=Gt-Mt-(Re?ee:0);Tt=I(nh(_n,Y,G)),_t=(B==0?Tt/2:B==K?0:Tt)-B*K*((B==0?L/2:0)+(Re?ee/2:0));const ge={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},cn=kt?null:new Path2D;let Xe=null;if(ut!=null)Xe=m.data[ut.series[1]];else{let{y0:Rt,y1:Xt}=l;Rt!=null&&Xt!=null&&(A=Xt.values(m,v,M,p),Xe=Rt.values(m,v,M,p))}let tn=k*Tt,O=lt*Tt;for(let Rt=K==1?M:p;Rt>=M&&Rt<=p;Rt+=K){let Xt=A[Rt];if(Xt==null)continue;if(Xe!=null){let X=Xe[Rt]??0;if(Xt-X==0)continue;pt=g(X,R,D,z)}let ne=y.distr!=2||l!=null?x[Rt]:Rt,yt=E(ne,y,U,T),De=g(xe(Xt,j),R,D,z),zt=I(yt-_t),Wt=I(kn(De,pt)),C=I(yi(De,pt)),S=Wt-C;if(Xt!=null){let X=Xt<0?O:tn,ht=Xt<0?tn:O;kt?(ee>0&&Qt[Rt]!=null&&Q(He.get(Qt[Rt]),zt,C+Qn(ee/2),Tt,kn(0,S-ee),X,ht),oe[Rt]!=null&&Q(se.get(oe[Rt]),zt,C+Qn(ee/2),Tt,kn(0,S-ee),X,ht)):Q(cn,zt,C+Qn(ee/2),Tt,kn(0,S-ee),X,ht),nt(m,v,Rt,zt-ee/2,C,Tt+ee,S)}}return ee>0?ge.stroke=kt?He:cn:kt||(ge._fill=f.width==0?f._fill:f._stroke??f._fill,ge.width=0),ge.fill=kt?se:cn,ge})}function cb(n,t){const e=xe(t?.alignGaps,0);return(i,s,r,a)=>Ys(i,s,(o,c,l,h,d,u,m,v,M,p,f)=>{[r,a]=Go(l,r,a);let x=o.pxRound,A=k=>x(u(k,h,p,v)),y=k=>x(m(k,d,f,M)),R,E,g;h.ori==0?(R=Yo,g=Or,E=tm):(R=qo,g=Br,E=em);const T=h.dir*(h.ori==0?1:-1);let z=A(c[T==1?r:a]),U=z,D=[],I=[];for(let k=T==1?r:a;k>=r&&k<=a;k+=T)if(l[k]!=null){let K=c[k],Q=A(K);D.push(U=Q),I.push(y(l[k]))}const B={stroke:n(D,I,R,g,E,x),fill:null,clip:null,band:null,gaps:null,flags:Nr},L=B.stroke;let[G,Y]=kh(i,s);if(o.fill!=null||G!=0){let k=B.fill=new Path2D(L),lt=o.fillTo(i,s,o.min,o.max,G),K=y(lt);g(k,U,K),g(k,z,K)}if(!o.spanGaps){let k=[];k.push(...Hh(c,l,r,a,T,A,e)),B.gaps=k=o.gaps(i,s,r,a,k),B.clip=$o(k,h.ori,v,M,p,f)}return Y!=0&&(B.band=Y==2?[ss(i,s,r,a,L,-1),ss(i,s,r,a,L,1)]:ss(i,s,r,a,L,Y)),B})}function hb(n){return cb(ub,n)}function ub(n,t,e,i,s,r){const a=n.length;if(a<2)return null;const o=new Path2D;if(e(o,n[0],t[0]),a==2)i(o,n[1],t[1]);else{let c=Array(a),l=Array(a-1),h=Array(a-1),d=Array(a-1);for(let u=0;u<a-1;u++)h[u]=t[u+1]-t[u],d[u]=n[u+1]-n[u],l[u]=h[u]/d[u];c[0]=l[0];for(let u=1;u<a-1;u++)l[u]===0||l[u-1]===0||l[u-1]>0!=l[u]>0?c[u]=0:(c[u]=3*(d[u-1]+d[u])/((2*d[u]+d[u-1])/l[u-1]+(d[u]+2*d[u-1])/l[u]),isFinite(c[u])||(c[u]=0));c[a-1]=l[a-2];for(let u=0;u<a-1;u++)s(o,n[u]+d[u]/3,t[u]+c[u]*d[u]/3,n[u+1]-d[u]/3,t[u+1]-c[u+1]*d[u]/3,n[u+1],t[u+1])}return o}const ah=new Set;function gf(){for(let n of ah)n.syncRect(!0)}Fr&&(Vs(Xy,wr,gf),Vs($y,wr,gf,!0),Vs(Io,wr,()=>{Dn.pxRatio=Me}));const db=sm(),fb=nm();function _f(n,t,e,i){return(i?[n[0],n[1]].concat(n.slice(2)):[n[0]].concat(n.slice(1))).map((r,a)=>oh(r,a,t,e))}function pb(n,t){return n.map((e,i)=>i==0?{}:on({},t,e))}function oh(n,t,e,i){return on({},t==0?e:i,n)}function rm(n,t,e){return t==null?Lr:[t,e]}const mb=rm;function gb(n,t,e){return t==null?Lr:Uo(t,e,Nh,!0)}function am(n,t,e,i){return t==null?Lr:Vo(t,e,n.scales[i].log,!1)}const _b=am;function om(n,t,e,i){return t==null?Lr:Dh(t,e,n.scales[i].log,!1)}const vb=om;function xb(n,t,e,i,s){let r=kn(qd(n),qd(t)),a=t-n,o=xi(s/i*a,e);do{let c=e[o],l=i*c/a;if(l>=s&&r+(c<5?Rs.get(c):0)<=17)return[c,l]}while(++o<e.length);return[0,0]}function vf(n){let t,e;return n=n.replace(/(\d+)px/,(i,s)=>(t=dn((e=+s)*Me))+"px"),[n,t,e]}function Sb(n){n.show&&[n.font,n.labelFont].forEach(t=>{let e=Ie(t[2]*Me,1);t[0]=t[0].replace(/[0-9.]+px/,e+"px"),t[1]=e})}function Dn(n,t,e){const i={mode:xe(n.mode,1)},s=i.mode;function r(_,b,P,N){let W=b.valToPct(_);return N+P*(b.dir==-1?1-W:W)}function a(_,b,P,N){let W=b.valToPct(_);return N+P*(b.dir==-1?W:1-W)}function o(_,b,P,N){return b.ori==0?r(_,b,P,N):a(_,b,P,N)}i.valToPosH=r,i.valToPosV=a;let c=!1;i.status=0;const l=i.root=ri(Ay);if(n.id!=null&&(l.id=n.id),Zn(l,n.class),n.title){let _=ri(Py,l);_.textContent=n.title}const h=vi("canvas"),d=i.ctx=h.getContext("2d"),u=ri(Ly,l);Vs("click",u,_=>{_.target===v&&(Oe!=tr||Ge!=er)&&An.click(i,_)},!0);const m=i.under=ri(Dy,u);u.appendChild(h);const v=i.over=ri(Ny,u);n=Dr(n);const M=+xe(n.pxAlign,1),p=pf(M);(n.plugins||[]).forEach(_=>{_.opts&&(n=_.opts(i,n)||n)});const f=n.ms||.001,x=i.series=s==1?_f(n.series||[],of,df,!1):pb(n.series||[null],uf),A=i.axes=_f(n.axes||[],af,cf,!0),y=i.scales={},R=i.bands=n.bands||[];R.forEach(_=>{_.fill=pe(_.fill||null),_.dir=xe(_.dir,-1)});const E=s==2?x[1].facets[0].scale:x[0].scale,g={axes:Xi,series:he},T=(n.drawOrder||["axes","series"]).map(_=>g[_]);function z(_){const b=_.distr==3?P=>is(P>0?P:_.clamp(i,P,_.min,_.max,_.key)):_.distr==4?P=>Ql(P,_.asinh):_.distr==100?P=>_.fwd(P):P=>P;return P=>{let N=b(P),{_min:W,_max:Z}=_,at=Z-W;return(N-W)/at}}function U(_){let b=y[_];if(b==null){let P=(n.scales||pa)[_]||pa;if(P.from!=null){U(P.from);let N=on({},y[P.from],P,{key:_});N.valToPct=z(N),y[_]=N}else{b=y[_]=on({},_==E?Kp:nb,P),b.key=_;let N=b.time,W=b.range,Z=vs(W);if((_!=E||s==2&&!N)&&(Z&&(W[0]==null||W[1]==null)&&(W={min:W[0]==null?Xd:{mode:1,hard:W[0],soft:W[0]},max:W[1]==null?Xd:{mode:1,hard:W[1],soft:W[1]}},Z=!1),!Z&&Xo(W))){let at=W;W=(dt,xt,Dt)=>xt==null?Lr:Uo(xt,Dt,at)}b.range=pe(W||(N?mb:_==E?b.distr==3?_b:b.distr==4?vb:rm:b.distr==3?am:b.distr==4?om:gb)),b.auto=pe(Z?!1:b.auto),b.clamp=pe(b.clamp||eb),b._min=b._max=null,b.valToPct=z(b)}}}U("x"),U("y"),s==1&&x.forEach(_=>{U(_.scale)}),A.forEach(_=>{U(_.scale)});for(let _ in n.scales)U(_);const D=y[E],I=D.distr;let B,L;D.ori==0?(Zn(l,Ry),B=r,L=a):(Zn(l,Cy),B=a,L=r);const G={};for(let _ in y){let b=y[_];(b.min!=null||b.max!=null)&&(G[_]={min:b.min,max:b.max},b.min=b.max=null)}const Y=n.tzDate||(_=>new Date(dn(_/f))),k=n.fmtDate||Fh,lt=f==1?RE(Y):LE(Y),K=nf(Y,ef(f==1?AE:PE,k)),Q=rf(Y,sf(NE,k)),nt=[],ut=i.legend=on({},FE,n.legend),ot=i.cursor=on({},GE,{drag:{y:s==2}},n.cursor),j=ut.show,pt=ot.show,_t=ut.markers;ut.idxs=nt,_t.width=pe(_t.width),_t.dash=pe(_t.dash),_t.stroke=pe(_t.stroke),_t.fill=pe(_t.fill);let Tt,Mt,Gt,ee=[],kt=[],oe,se=!1,Qt={};if(ut.live){const _=x[1]?x[1].values:null;se=_!=null,oe=se?_(i,1,0):{_:0};for(let b in oe)Qt[b]=Ph}if(j)if(Tt=vi("table",zy,l),Gt=vi("tbody",null,Tt),ut.mount(i,Tt),se){Mt=vi("thead",null,Tt,Gt);let _=vi("tr",null,Mt);vi("th",null,_);for(var He in oe)vi("th",Dd,_).textContent=He}else Zn(Tt,Hy),ut.live&&Zn(Tt,ky);const Ue={show:!0},je={show:!1};function Re(_,b){if(b==0&&(se||!ut.live||s==2))return Lr;let P=[],N=vi("tr",Gy,Gt,Gt.childNodes[b]);Zn(N,_.class),_.show||Zn(N,Hs);let W=vi("th",null,N);if(_t.show){let dt=ri(Vy,W);if(b>0){let xt=_t.width(i,b);xt&&(dt.style.border=xt+"px "+_t.dash(i,b)+" "+_t.stroke(i,b)),dt.style.background=_t.fill(i,b)}}let Z=ri(Dd,W);_.label instanceof HTMLElement?Z.appendChild(_.label):Z.textContent=_.label,b>0&&(_t.show||(Z.style.color=_.width>0?_t.stroke(i,b):_t.fill(i,b)),ge("click",W,dt=>{if(ot._lock)return;Yt(dt);let xt=x.indexOf(_);if((dt.ctrlKey||dt.metaKey)!=ut.isolate){let Dt=x.some((Nt,Ut)=>Ut>0&&Ut!=xt&&Nt.show);x.forEach((Nt,Ut)=>{Ut>0&&Ri(Ut,Dt?Ut==xt?Ue:je:Ue,!0,rn.setSeries)})}else Ri(xt,{show:!_.show},!0,rn.setSeries)},!1),qt&&ge(Fd,W,dt=>{ot._lock||(Yt(dt),Ri(x.indexOf(_),ir,!0,rn.setSeries))},!1));for(var at in oe){let dt=vi("td",Wy,N);dt.textContent="--",P.push(dt)}return[N,P]}const _n=new Map;function ge(_,b,P,N=!0){const W=_n.get(b)||{},Z=ot.bind[_](i,b,P,N);Z&&(Vs(_,b,W[_]=Z),_n.set(b,W))}function cn(_,b,P){const N=_n.get(b)||{};for(let W in N)(_==null||W==_)&&(eh(W,b,N[W]),delete N[W]);_==null&&_n.delete(b)}let Xe=0,tn=0,O=0,Rt=0,Xt=0,ne=0,yt=Xt,De=ne,zt=O,Wt=Rt,C=0,S=0,X=0,ht=0;i.bbox={};let rt=!1,gt=!1,vt=!1,tt=!1,it=!1,ft=!1;function F(_,b,P){(P||_!=i.width||b!=i.height)&&st(_,b),re(!1),vt=!0,gt=!0,Rn()}function st(_,b){i.width=Xe=O=_,i.height=tn=Rt=b,Xt=ne=0,St(),Ht();let P=i.bbox;C=P.left=zs(Xt*Me,.5),S=P.top=zs(ne*Me,.5),X=P.width=zs(O*Me,.5),ht=P.height=zs(Rt*Me,.5)}const et=3;function Et(){let _=!1,b=0;for(;!_;){b++;let P=Js(b),N=Ai(b);_=b==et||P&&N,_||(st(i.width,i.height),gt=!0)}}function mt({width:_,height:b}){F(_,b)}i.setSize=mt;function St(){let _=!1,b=!1,P=!1,N=!1;A.forEach((W,Z)=>{if(W.show&&W._show){let{side:at,_size:dt}=W,xt=at%2,Dt=W.label!=null?W.labelSize:0,Nt=dt+Dt;Nt>0&&(xt?(O-=Nt,at==3?(Xt+=Nt,N=!0):P=!0):(Rt-=Nt,at==0?(ne+=Nt,_=!0):b=!0))}}),wi[0]=_,wi[1]=P,wi[2]=b,wi[3]=N,O-=ui[1]+ui[3],Xt+=ui[3],Rt-=ui[2]+ui[0],ne+=ui[0]}function Ht(){let _=Xt+O,b=ne+Rt,P=Xt,N=ne;function W(Z,at){switch(Z){case 1:return _+=at,_-at;case 2:return b+=at,b-at;case 3:return P-=at,P+at;case 0:return N-=at,N+at}}A.forEach((Z,at)=>{if(Z.show&&Z._show){let dt=Z.side;Z._pos=W(dt,Z._size),Z.label!=null&&(Z._lpos=W(dt,Z.labelSize))}})}if(ot.dataIdx==null){let _=ot.hover,b=_.skip=new Set(_.skip??[]);b.add(void 0);let P=_.prox=pe(_.prox),N=_.bias??=0;ot.dataIdx=(W,Z,at,dt)=>{if(Z==0)return at;let xt=at,Dt=P(W,Z,at,dt)??Ne,Nt=Dt>=0&&Dt<Ne,Ut=D.ori==0?O:Rt,jt=ot.left,Se=t[0],_e=t[Z];if(b.has(_e[at])){xt=null;let ue=null,$t=null,Vt;if(N==0||N==-1)for(Vt=at;ue==null&&Vt-- >0;)b.has(_e[Vt])||(ue=Vt);if(N==0||N==1)for(Vt=at;$t==null&&Vt++<_e.length;)b.has(_e[Vt])||($t=Vt);if(ue!=null||$t!=null)if(Nt){let ze=ue==null?-1/0:B(Se[ue],D,Ut,0),qe=$t==null?1/0:B(Se[$t],D,Ut,0),Mn=jt-ze,Ce=qe-jt;Mn<=Ce?Mn<=Dt&&(xt=ue):Ce<=Dt&&(xt=$t)}else xt=$t==null?ue:ue==null?$t:at-ue<=$t-at?ue:$t}else Nt&&fn(jt-B(Se[at],D,Ut,0))>Dt&&(xt=null);return xt}}const Yt=_=>{ot.event=_};ot.idxs=nt,ot._lock=!1;let ct=ot.points;ct.show=pe(ct.show),ct.size=pe(ct.size),ct.stroke=pe(ct.stroke),ct.width=pe(ct.width),ct.fill=pe(ct.fill);const Ft=i.focus=on({},n.focus||{alpha:.3},ot.focus),qt=Ft.prox>=0,At=qt&&ct.one;let ie=[],Fe=[],Nn=[];function zr(_,b){let P=ct.show(i,b);if(P instanceof HTMLElement)return Zn(P,By),Zn(P,_.class),Ui(P,-10,-10,O,Rt),v.insertBefore(P,ie[b]),P}function qs(_,b){if(s==1||b>0){let P=s==1&&y[_.scale].time,N=_.value;_.value=P?Jd(N)?rf(Y,sf(N,k)):N||Q:N||QE,_.label=_.label||(P?WE:VE)}if(At||b>0){_.width=_.width==null?1:_.width,_.paths=_.paths||db||nE,_.fillTo=pe(_.fillTo||ib),_.pxAlign=+xe(_.pxAlign,M),_.pxRound=pf(_.pxAlign),_.stroke=pe(_.stroke||null),_.fill=pe(_.fill||null),_._stroke=_._fill=_._paths=_._focus=null;let P=jE(kn(1,_.width),1),N=_.points=on({},{size:P,width:kn(1,P*.2),stroke:_.stroke,space:P*2,paths:fb,_stroke:null,_fill:null},_.points);N.show=pe(N.show),N.filter=pe(N.filter),N.fill=pe(N.fill),N.stroke=pe(N.stroke),N.paths=pe(N.paths),N.pxAlign=_.pxAlign}if(j){let P=Re(_,b);ee.splice(b,0,P[0]),kt.splice(b,0,P[1]),ut.values.push(null)}if(pt){nt.splice(b,0,null);let P=null;At?b==0&&(P=zr(_,b)):b>0&&(P=zr(_,b)),ie.splice(b,0,P),Fe.splice(b,0,0),Nn.splice(b,0,0)}Sn("addSeries",b)}function Zo(_,b){b=b??x.length,_=s==1?oh(_,b,of,df):oh(_,b,{},uf),x.splice(b,0,_),qs(x[b],b)}i.addSeries=Zo;function Ca(_){if(x.splice(_,1),j){ut.values.splice(_,1),kt.splice(_,1);let b=ee.splice(_,1)[0];cn(null,b.firstChild),b.remove()}pt&&(nt.splice(_,1),ie.splice(_,1)[0].remove(),Fe.splice(_,1),Nn.splice(_,1)),Sn("delSeries",_)}i.delSeries=Ca;const wi=[!1,!1,!1,!1];function Gi(_,b){if(_._show=_.show,_.show){let P=_.side%2,N=y[_.scale];N==null&&(_.scale=P?x[1].scale:E,N=y[_.scale]);let W=N.time;_.size=pe(_.size),_.space=pe(_.space),_.rotate=pe(_.rotate),vs(_.incrs)&&_.incrs.forEach(at=>{!Rs.has(at)&&Rs.set(at,Pp(at))}),_.incrs=pe(_.incrs||(N.distr==2?bE:W?f==1?TE:CE:ks)),_.splits=pe(_.splits||(W&&N.distr==1?lt:N.distr==3?ih:N.distr==4?YE:$E)),_.stroke=pe(_.stroke),_.grid.stroke=pe(_.grid.stroke),_.ticks.stroke=pe(_.ticks.stroke),_.border.stroke=pe(_.border.stroke);let Z=_.values;_.values=vs(Z)&&!vs(Z[0])?pe(Z):W?vs(Z)?nf(Y,ef(Z,k)):Jd(Z)?DE(Y,Z):Z||K:Z||XE,_.filter=pe(_.filter||(N.distr>=3&&N.log==10?ZE:N.distr==3&&N.log==2?JE:Rp)),_.font=vf(_.font),_.labelFont=vf(_.labelFont),_._size=_.size(i,null,b,0),_._space=_._rotate=_._incrs=_._found=_._splits=_._values=null,_._size>0&&(wi[b]=!0,_._el=ri(Iy,u))}}function Vi(_,b,P,N){let[W,Z,at,dt]=P,xt=b%2,Dt=0;return xt==0&&(dt||Z)&&(Dt=b==0&&!W||b==2&&!at?dn(af.size/3):0),xt==1&&(W||at)&&(Dt=b==1&&!Z||b==3&&!dt?dn(cf.size/2):0),Dt}const kr=i.padding=(n.padding||[Vi,Vi,Vi,Vi]).map(_=>pe(xe(_,Vi))),ui=i._padding=kr.map((_,b)=>_(i,b,wi,0));let $e,Ze=null,Je=null;const Ti=s==1?x[0].idxs:null;let Wn=null,as=!1;function Hr(_,b){if(t=_??[],i.data=i._data=t,s==2){$e=0;for(let P=1;P<x.length;P++)$e+=t[P][0].length}else{t.length==0&&(i.data=i._data=t=[[]]),Wn=t[0],$e=Wn.length;let P=t;if(I==2){P=t.slice();let N=P[0]=Array($e);for(let W=0;W<$e;W++)N[W]=W}i._data=t=P}if(re(!0),Sn("setData"),I==2&&(vt=!0),b!==!1){let P=D;P.auto(i,as)?Gr():cs(E,P.min,P.max),tt=tt||ot.left>=0,ft=!0,Rn()}}i.setData=Hr;function Gr(){as=!0;let _,b;s==1&&($e>0?(Ze=Ti[0]=0,Je=Ti[1]=$e-1,_=t[0][Ze],b=t[0][Je],I==2?(_=Ze,b=Je):_==b&&(I==3?[_,b]=Vo(_,_,D.log,!1):I==4?[_,b]=Dh(_,_,D.log,!1):D.time?b=_+dn(86400/f):[_,b]=Uo(_,b,Nh,!0))):(Ze=Ti[0]=_=null,Je=Ti[1]=b=null)),cs(E,_,b)}let Ks,os,Zs,w,H,J,$,q,bt,Ct;function wt(_,b,P,N,W,Z){_??=Id,P??=Uh,N??="butt",W??=Id,Z??="round",_!=Ks&&(d.strokeStyle=Ks=_),W!=os&&(d.fillStyle=os=W),b!=Zs&&(d.lineWidth=Zs=b),Z!=H&&(d.lineJoin=H=Z),N!=J&&(d.lineCap=J=N),P!=w&&d.setLineDash(w=P)}function Pt(_,b,P,N){b!=os&&(d.fillStyle=os=b),_!=$&&(d.font=$=_),P!=q&&(d.textAlign=q=P),N!=bt&&(d.textBaseline=bt=N)}function Bt(_,b,P,N,W=0){if(N.length>0&&_.auto(i,as)&&(b==null||b.min==null)){let Z=xe(Ze,0),at=xe(Je,N.length-1),dt=P.min==null?Zy(N,Z,at,W,_.distr==3):[P.min,P.max];_.min=yi(_.min,P.min=dt[0]),_.max=kn(_.max,P.max=dt[1])}}const Zt={min:null,max:null};function ce(){for(let N in y){let W=y[N];G[N]==null&&(W.min==null||G[E]!=null&&W.auto(i,as))&&(G[N]=Zt)}for(let N in y){let W=y[N];G[N]==null&&W.from!=null&&G[W.from]!=null&&(G[N]=Zt)}G[E]!=null&&re(!0);let _={};for(let N in G){let W=G[N];if(W!=null){let Z=_[N]=Dr(y[N],rE);if(W.min!=null)on(Z,W);else if(N!=E||s==2)if($e==0&&Z.from==null){let at=Z.range(i,null,null,N);Z.min=at[0],Z.max=at[1]}else Z.min=Ne,Z.max=-Ne}}if($e>0){x.forEach((N,W)=>{if(s==1){let Z=N.scale,at=G[Z];if(at==null)return;let dt=_[Z];if(W==0){let xt=dt.range(i,dt.min,dt.max,Z);dt.min=xt[0],dt.max=xt[1],Ze=xi(dt.min,t[0]),Je=xi(dt.max,t[0]),Je-Ze>1&&(t[0][Ze]<dt.min&&Ze++,t[0][Je]>dt.max&&Je--),N.min=Wn[Ze],N.max=Wn[Je]}else N.show&&N.auto&&Bt(dt,at,N,t[W],N.sorted);N.idxs[0]=Ze,N.idxs[1]=Je}else if(W>0&&N.show&&N.auto){let[Z,at]=N.facets,dt=Z.scale,xt=at.scale,[Dt,Nt]=t[W],Ut=_[dt],jt=_[xt];Ut!=null&&Bt(Ut,G[dt],Z,Dt,Z.sorted),jt!=null&&Bt(jt,G[xt],at,Nt,at.sorted),N.min=at.min,N.max=at.max}});for(let N in _){let W=_[N],Z=G[N];if(W.from==null&&(Z==null||Z.min==null)){let at=W.range(i,W.min==Ne?null:W.min,W.max==-Ne?null:W.max,N);W.min=at[0],W.max=at[1]}}}for(let N in _){let W=_[N];if(W.from!=null){let Z=_[W.from];if(Z.min==null)W.min=W.max=null;else{let at=W.range(i,Z.min,Z.max,N);W.min=at[0],W.max=at[1]}}}let b={},P=!1;for(let N in _){let W=_[N],Z=y[N];if(Z.min!=W.min||Z.max!=W.max){Z.min=W.min,Z.max=W.max;let at=Z.distr;Z._min=at==3?is(Z.min):at==4?Ql(Z.min,Z.asinh):at==100?Z.fwd(Z.min):Z.min,Z._max=at==3?is(Z.max):at==4?Ql(Z.max,Z.asinh):at==100?Z.fwd(Z.max):Z.max,b[N]=P=!0}}if(P){x.forEach((N,W)=>{s==2?W>0&&b.y&&(N._paths=null):b[N.scale]&&(N._paths=null)});for(let N in b)vt=!0,Sn("setScale",N);pt&&ot.left>=0&&(tt=ft=!0)}for(let N in G)G[N]=null}function Ot(_){let b=nh(Ze-1,0,$e-1),P=nh(Je+1,0,$e-1);for(;_[b]==null&&b>0;)b--;for(;_[P]==null&&P<$e-1;)P++;return[b,P]}function he(){if($e>0){let _=x.some(b=>b._focus)&&Ct!=Ft.alpha;_&&(d.globalAlpha=Ct=Ft.alpha),x.forEach((b,P)=>{if(P>0&&b.show&&(Ve(P,!1),Ve(P,!0),b._paths==null)){let N=Ct;Ct!=b.alpha&&(d.globalAlpha=Ct=b.alpha);let W=s==2?[0,t[P][0].length-1]:Ot(t[P]);b._paths=b.paths(i,P,W[0],W[1]),Ct!=N&&(d.globalAlpha=Ct=N)}}),x.forEach((b,P)=>{if(P>0&&b.show){let N=Ct;Ct!=b.alpha&&(d.globalAlpha=Ct=b.alpha),b._paths!=null&&be(P,!1);{let W=b._paths!=null?b._paths.gaps:null,Z=b.points.show(i,P,Ze,Je,W),at=b.points.filter(i,P,Z,W);(Z||at)&&(b.points._paths=b.points.paths(i,P,Ze,Je,at),be(P,!0))}Ct!=N&&(d.globalAlpha=Ct=N),Sn("drawSeries",P)}}),_&&(d.globalAlpha=Ct=1)}}function Ve(_,b){let P=b?x[_].points:x[_];P._stroke=P.stroke(i,_),P._fill=P.fill(i,_)}function be(_,b){let P=b?x[_].points:x[_],{stroke:N,fill:W,clip:Z,flags:at,_stroke:dt=P._stroke,_fill:xt=P._fill,_width:Dt=P.width}=P._paths;Dt=Ie(Dt*Me,3);let Nt=null,Ut=Dt%2/2;b&&xt==null&&(xt=Dt>0?"#fff":dt);let jt=P.pxAlign==1&&Ut>0;if(jt&&d.translate(Ut,Ut),!b){let Se=C-Dt/2,_e=S-Dt/2,ue=X+Dt,$t=ht+Dt;Nt=new Path2D,Nt.rect(Se,_e,ue,$t)}b?It(dt,Dt,P.dash,P.cap,xt,N,W,at,Z):we(_,dt,Dt,P.dash,P.cap,xt,N,W,at,Nt,Z),jt&&d.translate(-Ut,-Ut)}function we(_,b,P,N,W,Z,at,dt,xt,Dt,Nt){let Ut=!1;xt!=0&&R.forEach((jt,Se)=>{if(jt.series[0]==_){let _e=x[jt.series[1]],ue=t[jt.series[1]],$t=(_e._paths||pa).band;vs($t)&&($t=jt.dir==1?$t[0]:$t[1]);let Vt,ze=null;_e.show&&$t&&Qy(ue,Ze,Je)?(ze=jt.fill(i,Se)||Z,Vt=_e._paths.clip):$t=null,It(b,P,N,W,ze,at,dt,xt,Dt,Nt,Vt,$t),Ut=!0}}),Ut||It(b,P,N,W,Z,at,dt,xt,Dt,Nt)}const hn=Nr|rh;function It(_,b,P,N,W,Z,at,dt,xt,Dt,Nt,Ut){wt(_,b,P,N,W),(xt||Dt||Ut)&&(d.save(),xt&&d.clip(xt),Dt&&d.clip(Dt)),Ut?(dt&hn)==hn?(d.clip(Ut),Nt&&d.clip(Nt),fe(W,at),en(_,Z,b)):dt&rh?(fe(W,at),d.clip(Ut),en(_,Z,b)):dt&Nr&&(d.save(),d.clip(Ut),Nt&&d.clip(Nt),fe(W,at),d.restore(),en(_,Z,b)):(fe(W,at),en(_,Z,b)),(xt||Dt||Ut)&&d.restore()}function en(_,b,P){P>0&&(b instanceof Map?b.forEach((N,W)=>{d.strokeStyle=Ks=W,d.stroke(N)}):b!=null&&_&&d.stroke(b))}function fe(_,b){b instanceof Map?b.forEach((P,N)=>{d.fillStyle=os=N,d.fill(P)}):b!=null&&_&&d.fill(b)}function Wi(_,b,P,N){let W=A[_],Z;if(N<=0)Z=[0,0];else{let at=W._space=W.space(i,_,b,P,N),dt=W._incrs=W.incrs(i,_,b,P,N,at);Z=xb(b,P,dt,N,at)}return W._found=Z}function nn(_,b,P,N,W,Z,at,dt,xt,Dt){let Nt=at%2/2;M==1&&d.translate(Nt,Nt),wt(dt,at,xt,Dt,dt),d.beginPath();let Ut,jt,Se,_e,ue=W+(N==0||N==3?-Z:Z);P==0?(jt=W,_e=ue):(Ut=W,Se=ue);for(let $t=0;$t<_.length;$t++)b[$t]!=null&&(P==0?Ut=Se=_[$t]:jt=_e=_[$t],d.moveTo(Ut,jt),d.lineTo(Se,_e));d.stroke(),M==1&&d.translate(-Nt,-Nt)}function Js(_){let b=!0;return A.forEach((P,N)=>{if(!P.show)return;let W=y[P.scale];if(W.min==null){P._show&&(b=!1,P._show=!1,re(!1));return}else P._show||(b=!1,P._show=!0,re(!1));let Z=P.side,at=Z%2,{min:dt,max:xt}=W,[Dt,Nt]=Wi(N,dt,xt,at==0?O:Rt);if(Nt==0)return;let Ut=W.distr==2,jt=P._splits=P.splits(i,N,dt,xt,Dt,Nt,Ut),Se=W.distr==2?jt.map(Vt=>Wn[Vt]):jt,_e=W.distr==2?Wn[jt[1]]-Wn[jt[0]]:Dt,ue=P._values=P.values(i,P.filter(i,Se,N,Nt,_e),N,Nt,_e);P._rotate=Z==2?P.rotate(i,ue,N,Nt):0;let $t=P._size;P._size=oi(P.size(i,ue,N,_)),$t!=null&&P._size!=$t&&(b=!1)}),b}function Ai(_){let b=!0;return kr.forEach((P,N)=>{let W=P(i,N,wi,_);W!=ui[N]&&(b=!1),ui[N]=W}),b}function Xi(){for(let _=0;_<A.length;_++){let b=A[_];if(!b.show||!b._show)continue;let P=b.side,N=P%2,W,Z,at=b.stroke(i,_),dt=P==0||P==3?-1:1,[xt,Dt]=b._found;if(b.label!=null){let Fn=b.labelGap*dt,Yn=dn((b._lpos+Fn)*Me);Pt(b.labelFont[0],at,"center",P==2?na:Nd),d.save(),N==1?(W=Z=0,d.translate(Yn,dn(S+ht/2)),d.rotate((P==3?-bo:bo)/2)):(W=dn(C+X/2),Z=Yn);let Ds=Tp(b.label)?b.label(i,_,xt,Dt):b.label;d.fillText(Ds,W,Z),d.restore()}if(Dt==0)continue;let Nt=y[b.scale],Ut=N==0?X:ht,jt=N==0?C:S,Se=b._splits,_e=Nt.distr==2?Se.map(Fn=>Wn[Fn]):Se,ue=Nt.distr==2?Wn[Se[1]]-Wn[Se[0]]:xt,$t=b.ticks,Vt=b.border,ze=$t.show?$t.size:0,qe=dn(ze*Me),Mn=dn((b.alignTo==2?b._size-ze-b.gap:b.gap)*Me),Ce=b._rotate*-bo/180,Ke=p(b._pos*Me),Xn=(qe+Mn)*dt,Un=Ke+Xn;Z=N==0?Un:0,W=N==1?Un:0;let ti=b.font[0],di=b.align==1?_r:b.align==2?Kl:Ce>0?_r:Ce<0?Kl:N==0?"center":P==3?Kl:_r,Pi=Ce||N==1?"middle":P==2?na:Nd;Pt(ti,at,di,Pi);let $n=b.font[1]*b.lineGap,ei=Se.map(Fn=>p(o(Fn,Nt,Ut,jt))),fi=b._values;for(let Fn=0;Fn<fi.length;Fn++){let Yn=fi[Fn];if(Yn!=null){N==0?W=ei[Fn]:Z=ei[Fn],Yn=""+Yn;let Ds=Yn.indexOf(`
`)==-1?[Yn]:Yn.split(/\n/gm);for(let On=0;On<Ds.length;On++){let lu=Ds[On];Ce?(d.save(),d.translate(W,Z+On*$n),d.rotate(Ce),d.fillText(lu,0,0),d.restore()):d.fillText(lu,W,Z+On*$n)}}}$t.show&&nn(ei,$t.filter(i,_e,_,Dt,ue),N,P,Ke,qe,Ie($t.width*Me,3),$t.stroke(i,_),$t.dash,$t.cap);let Li=b.grid;Li.show&&nn(ei,Li.filter(i,_e,_,Dt,ue),N,N==0?2:1,N==0?S:C,N==0?ht:X,Ie(Li.width*Me,3),Li.stroke(i,_),Li.dash,Li.cap),Vt.show&&nn([Ke],[1],N==0?1:0,N==0?1:2,N==1?S:C,N==1?ht:X,Ie(Vt.width*Me,3),Vt.stroke(i,_),Vt.dash,Vt.cap)}Sn("drawAxes")}function re(_){x.forEach((b,P)=>{P>0&&(b._paths=null,_&&(s==1?(b.min=null,b.max=null):b.facets.forEach(N=>{N.min=null,N.max=null})))})}let Ye=!1,In=!1,Te=[];function sn(){In=!1;for(let _=0;_<Te.length;_++)Sn(...Te[_]);Te.length=0}function Rn(){Ye||(dE(Wh),Ye=!0)}function Pa(_,b=!1){Ye=!0,In=b,_(i),Wh(),b&&Te.length>0&&queueMicrotask(sn)}i.batch=Pa;function Wh(){if(rt&&(ce(),rt=!1),vt&&(Et(),vt=!1),gt){if(ke(m,_r,Xt),ke(m,na,ne),ke(m,oa,O),ke(m,la,Rt),ke(v,_r,Xt),ke(v,na,ne),ke(v,oa,O),ke(v,la,Rt),ke(u,oa,Xe),ke(u,la,tn),h.width=dn(Xe*Me),h.height=dn(tn*Me),A.forEach(({_el:_,_show:b,_size:P,_pos:N,side:W})=>{if(_!=null)if(b){let Z=W===3||W===0?P:0,at=W%2==1;ke(_,at?"left":"top",N-Z),ke(_,at?"width":"height",P),ke(_,at?"top":"left",at?ne:Xt),ke(_,at?"height":"width",at?Rt:O),th(_,Hs)}else Zn(_,Hs)}),Ks=os=Zs=H=J=$=q=bt=w=null,Ct=1,Xr(!0),Xt!=yt||ne!=De||O!=zt||Rt!=Wt){re(!1);let _=O/zt,b=Rt/Wt;if(pt&&!tt&&ot.left>=0){ot.left*=_,ot.top*=b,Qs&&Ui(Qs,dn(ot.left),0,O,Rt),js&&Ui(js,0,dn(ot.top),O,Rt);for(let P=0;P<ie.length;P++){let N=ie[P];N!=null&&(Fe[P]*=_,Nn[P]*=b,Ui(N,oi(Fe[P]),oi(Nn[P]),O,Rt))}}if(Be.show&&!it&&Be.left>=0&&Be.width>0){Be.left*=_,Be.width*=_,Be.top*=b,Be.height*=b;for(let P in nl)ke(nr,P,Be[P])}yt=Xt,De=ne,zt=O,Wt=Rt}Sn("setSize"),gt=!1}Xe>0&&tn>0&&(d.clearRect(0,0,h.width,h.height),Sn("drawClear"),T.forEach(_=>_()),Sn("draw")),Be.show&&it&&(La(Be),it=!1),pt&&tt&&(Ls(null,!0,!1),tt=!1),ut.show&&ut.live&&ft&&(tl(),ft=!1),c||(c=!0,i.status=1,Sn("ready")),as=!1,Ye=!1}i.redraw=(_,b)=>{vt=b||!1,_!==!1?cs(E,D.min,D.max):Rn()};function Jo(_,b){let P=y[_];if(P.from==null){if($e==0){let N=P.range(i,b.min,b.max,_);b.min=N[0],b.max=N[1]}if(b.min>b.max){let N=b.min;b.min=b.max,b.max=N}if($e>1&&b.min!=null&&b.max!=null&&b.max-b.min<1e-16)return;_==E&&P.distr==2&&$e>0&&(b.min=xi(b.min,t[0]),b.max=xi(b.max,t[0]),b.min==b.max&&b.max++),G[_]=b,rt=!0,Rn()}}i.setScale=Jo;let Qo,jo,Qs,js,Xh,$h,tr,er,Yh,qh,Oe,Ge,ls=!1;const An=ot.drag;let vn=An.x,xn=An.y;pt&&(ot.x&&(Qo=ri(Fy,v)),ot.y&&(jo=ri(Oy,v)),D.ori==0?(Qs=Qo,js=jo):(Qs=jo,js=Qo),Oe=ot.left,Ge=ot.top);const Be=i.select=on({show:!0,over:!0,left:0,width:0,top:0,height:0},n.select),nr=Be.show?ri(Uy,Be.over?v:m):null;function La(_,b){if(Be.show){for(let P in _)Be[P]=_[P],P in nl&&ke(nr,P,_[P]);b!==!1&&Sn("setSelect")}}i.setSelect=La;function cm(_){if(x[_].show)j&&th(ee[_],Hs);else if(j&&Zn(ee[_],Hs),pt){let P=At?ie[0]:ie[_];P!=null&&Ui(P,-10,-10,O,Rt)}}function cs(_,b,P){Jo(_,{min:b,max:P})}function Ri(_,b,P,N){b.focus!=null&&pm(_),b.show!=null&&x.forEach((W,Z)=>{Z>0&&(_==Z||_==null)&&(W.show=b.show,cm(Z),s==2?(cs(W.facets[0].scale,null,null),cs(W.facets[1].scale,null,null)):cs(W.scale,null,null),Rn())}),P!==!1&&Sn("setSeries",_,b),N&&$r("setSeries",i,_,b)}i.setSeries=Ri;function hm(_,b){on(R[_],b)}function um(_,b){_.fill=pe(_.fill||null),_.dir=xe(_.dir,-1),b=b??R.length,R.splice(b,0,_)}function dm(_){_==null?R.length=0:R.splice(_,1)}i.addBand=um,i.setBand=hm,i.delBand=dm;function fm(_,b){x[_].alpha=b,pt&&ie[_]!=null&&(ie[_].style.opacity=b),j&&ee[_]&&(ee[_].style.opacity=b)}let $i,hs,Ps;const ir={focus:!0};function pm(_){if(_!=Ps){let b=_==null,P=Ft.alpha!=1;x.forEach((N,W)=>{if(s==1||W>0){let Z=b||W==0||W==_;N._focus=b?null:Z,P&&fm(W,Z?1:Ft.alpha)}}),Ps=_,P&&Rn()}}j&&qt&&ge(Od,Tt,_=>{ot._lock||(Yt(_),Ps!=null&&Ri(null,ir,!0,rn.setSeries))});function Ci(_,b,P){let N=y[b];P&&(_=_/Me-(N.ori==1?ne:Xt));let W=O;N.ori==1&&(W=Rt,_=W-_),N.dir==-1&&(_=W-_);let Z=N._min,at=N._max,dt=_/W,xt=Z+(at-Z)*dt,Dt=N.distr;return Dt==3?Pr(10,xt):Dt==4?tE(xt,N.asinh):Dt==100?N.bwd(xt):xt}function mm(_,b){let P=Ci(_,E,b);return xi(P,t[0],Ze,Je)}i.valToIdx=_=>xi(_,t[0]),i.posToIdx=mm,i.posToVal=Ci,i.valToPos=(_,b,P)=>y[b].ori==0?r(_,y[b],P?X:O,P?C:0):a(_,y[b],P?ht:Rt,P?S:0),i.setCursor=(_,b,P)=>{Oe=_.left,Ge=_.top,Ls(null,b,P)};function Kh(_,b){ke(nr,_r,Be.left=_),ke(nr,oa,Be.width=b)}function Zh(_,b){ke(nr,na,Be.top=_),ke(nr,la,Be.height=b)}let Vr=D.ori==0?Kh:Zh,Wr=D.ori==1?Kh:Zh;function gm(){if(j&&ut.live)for(let _=s==2?1:0;_<x.length;_++){if(_==0&&se)continue;let b=ut.values[_],P=0;for(let N in b)kt[_][P++].firstChild.nodeValue=b[N]}}function tl(_,b){if(_!=null&&(_.idxs?_.idxs.forEach((P,N)=>{nt[N]=P}):sE(_.idx)||nt.fill(_.idx),ut.idx=nt[0]),j&&ut.live){for(let P=0;P<x.length;P++)(P>0||s==1&&!se)&&_m(P,nt[P]);gm()}ft=!1,b!==!1&&Sn("setLegend")}i.setLegend=tl;function _m(_,b){let P=x[_],N=_==0&&I==2?Wn:t[_],W;se?W=P.values(i,_,b)??Qt:(W=P.value(i,b==null?null:N[b],_,b),W=W==null?Qt:{_:W}),ut.values[_]=W}function Ls(_,b,P){Yh=Oe,qh=Ge,[Oe,Ge]=ot.move(i,Oe,Ge),ot.left=Oe,ot.top=Ge,pt&&(Qs&&Ui(Qs,dn(Oe),0,O,Rt),js&&Ui(js,0,dn(Ge),O,Rt));let N,W=Ze>Je;$i=Ne,hs=null;let Z=D.ori==0?O:Rt,at=D.ori==1?O:Rt;if(Oe<0||$e==0||W){N=ot.idx=null;for(let dt=0;dt<x.length;dt++){let xt=ie[dt];xt!=null&&Ui(xt,-10,-10,O,Rt)}qt&&Ri(null,ir,!0,_==null&&rn.setSeries),ut.live&&(nt.fill(N),ft=!0)}else{let dt,xt,Dt;s==1&&(dt=D.ori==0?Oe:Ge,xt=Ci(dt,E),N=ot.idx=xi(xt,t[0],Ze,Je),Dt=B(t[0][N],D,Z,0));let Nt=-10,Ut=-10,jt=0,Se=0,_e=!0,ue="",$t="";for(let Vt=s==2?1:0;Vt<x.length;Vt++){let ze=x[Vt],qe=nt[Vt],Mn=qe==null?null:s==1?t[Vt][qe]:t[Vt][1][qe],Ce=ot.dataIdx(i,Vt,N,xt),Ke=Ce==null?null:s==1?t[Vt][Ce]:t[Vt][1][Ce];if(ft=ft||Ke!=Mn||Ce!=qe,nt[Vt]=Ce,Vt>0&&ze.show){let Xn=Ce==null?-10:Ce==N?Dt:B(s==1?t[0][Ce]:t[Vt][0][Ce],D,Z,0),Un=Ke==null?-10:L(Ke,s==1?y[ze.scale]:y[ze.facets[1].scale],at,0);if(qt&&Ke!=null){let ti=D.ori==1?Oe:Ge,di=fn(Ft.dist(i,Vt,Ce,Un,ti));if(di<$i){let Pi=Ft.bias;if(Pi!=0){let $n=Ci(ti,ze.scale),ei=Ke>=0?1:-1,fi=$n>=0?1:-1;fi==ei&&(fi==1?Pi==1?Ke>=$n:Ke<=$n:Pi==1?Ke<=$n:Ke>=$n)&&($i=di,hs=Vt)}else $i=di,hs=Vt}}if(ft||At){let ti,di;D.ori==0?(ti=Xn,di=Un):(ti=Un,di=Xn);let Pi,$n,ei,fi,Li,Fn,Yn=!0,Ds=ct.bbox;if(Ds!=null){Yn=!1;let On=Ds(i,Vt);ei=On.left,fi=On.top,Pi=On.width,$n=On.height}else ei=ti,fi=di,Pi=$n=ct.size(i,Vt);if(Fn=ct.fill(i,Vt),Li=ct.stroke(i,Vt),At)Vt==hs&&$i<=Ft.prox&&(Nt=ei,Ut=fi,jt=Pi,Se=$n,_e=Yn,ue=Fn,$t=Li);else{let On=ie[Vt];On!=null&&(Fe[Vt]=ei,Nn[Vt]=fi,Wd(On,Pi,$n,Yn),Gd(On,Fn,Li),Ui(On,oi(ei),oi(fi),O,Rt))}}}}if(At){let Vt=Ft.prox,ze=Ps==null?$i<=Vt:$i>Vt||hs!=Ps;if(ft||ze){let qe=ie[0];qe!=null&&(Fe[0]=Nt,Nn[0]=Ut,Wd(qe,jt,Se,_e),Gd(qe,ue,$t),Ui(qe,oi(Nt),oi(Ut),O,Rt))}}}if(Be.show&&ls)if(_!=null){let[dt,xt]=rn.scales,[Dt,Nt]=rn.match,[Ut,jt]=_.cursor.sync.scales,Se=_.cursor.drag;if(vn=Se._x,xn=Se._y,vn||xn){let{left:_e,top:ue,width:$t,height:Vt}=_.select,ze=_.scales[Ut].ori,qe=_.posToVal,Mn,Ce,Ke,Xn,Un,ti=dt!=null&&Dt(dt,Ut),di=xt!=null&&Nt(xt,jt);ti&&vn?(ze==0?(Mn=_e,Ce=$t):(Mn=ue,Ce=Vt),Ke=y[dt],Xn=B(qe(Mn,Ut),Ke,Z,0),Un=B(qe(Mn+Ce,Ut),Ke,Z,0),Vr(yi(Xn,Un),fn(Un-Xn))):Vr(0,Z),di&&xn?(ze==1?(Mn=_e,Ce=$t):(Mn=ue,Ce=Vt),Ke=y[xt],Xn=L(qe(Mn,jt),Ke,at,0),Un=L(qe(Mn+Ce,jt),Ke,at,0),Wr(yi(Xn,Un),fn(Un-Xn))):Wr(0,at)}else il()}else{let dt=fn(Yh-Xh),xt=fn(qh-$h);if(D.ori==1){let jt=dt;dt=xt,xt=jt}vn=An.x&&dt>=An.dist,xn=An.y&&xt>=An.dist;let Dt=An.uni;Dt!=null?vn&&xn&&(vn=dt>=Dt,xn=xt>=Dt,!vn&&!xn&&(xt>dt?xn=!0:vn=!0)):An.x&&An.y&&(vn||xn)&&(vn=xn=!0);let Nt,Ut;vn&&(D.ori==0?(Nt=tr,Ut=Oe):(Nt=er,Ut=Ge),Vr(yi(Nt,Ut),fn(Ut-Nt)),xn||Wr(0,at)),xn&&(D.ori==1?(Nt=tr,Ut=Oe):(Nt=er,Ut=Ge),Wr(yi(Nt,Ut),fn(Ut-Nt)),vn||Vr(0,Z)),!vn&&!xn&&(Vr(0,0),Wr(0,0))}if(An._x=vn,An._y=xn,_==null){if(P){if(ou!=null){let[dt,xt]=rn.scales;rn.values[0]=dt!=null?Ci(D.ori==0?Oe:Ge,dt):null,rn.values[1]=xt!=null?Ci(D.ori==1?Oe:Ge,xt):null}$r(Zl,i,Oe,Ge,O,Rt,N)}if(qt){let dt=P&&rn.setSeries,xt=Ft.prox;Ps==null?$i<=xt&&Ri(hs,ir,!0,dt):$i>xt?Ri(null,ir,!0,dt):hs!=Ps&&Ri(hs,ir,!0,dt)}}ft&&(ut.idx=N,tl()),b!==!1&&Sn("setCursor")}let us=null;Object.defineProperty(i,"rect",{get(){return us==null&&Xr(!1),us}});function Xr(_=!1){_?us=null:(us=v.getBoundingClientRect(),Sn("syncRect",us))}function Jh(_,b,P,N,W,Z,at){ot._lock||ls&&_!=null&&_.movementX==0&&_.movementY==0||(el(_,b,P,N,W,Z,at,!1,_!=null),_!=null?Ls(null,!0,!0):Ls(b,!0,!1))}function el(_,b,P,N,W,Z,at,dt,xt){if(us==null&&Xr(!1),Yt(_),_!=null)P=_.clientX-us.left,N=_.clientY-us.top;else{if(P<0||N<0){Oe=-10,Ge=-10;return}let[Dt,Nt]=rn.scales,Ut=b.cursor.sync,[jt,Se]=Ut.values,[_e,ue]=Ut.scales,[$t,Vt]=rn.match,ze=b.axes[0].side%2==1,qe=D.ori==0?O:Rt,Mn=D.ori==1?O:Rt,Ce=ze?Z:W,Ke=ze?W:Z,Xn=ze?N:P,Un=ze?P:N;if(_e!=null?P=$t(Dt,_e)?o(jt,y[Dt],qe,0):-10:P=qe*(Xn/Ce),ue!=null?N=Vt(Nt,ue)?o(Se,y[Nt],Mn,0):-10:N=Mn*(Un/Ke),D.ori==1){let ti=P;P=N,N=ti}}xt&&(b==null||b.cursor.event.type==Zl)&&((P<=1||P>=O-1)&&(P=zs(P,O)),(N<=1||N>=Rt-1)&&(N=zs(N,Rt))),dt?(Xh=P,$h=N,[tr,er]=ot.move(i,P,N)):(Oe=P,Ge=N)}const nl={width:0,height:0,left:0,top:0};function il(){La(nl,!1)}let Qh,jh,tu,eu;function nu(_,b,P,N,W,Z,at){ls=!0,vn=xn=An._x=An._y=!1,el(_,b,P,N,W,Z,at,!0,!1),_!=null&&(ge(Jl,Qc,iu,!1),$r(Ud,i,tr,er,O,Rt,null));let{left:dt,top:xt,width:Dt,height:Nt}=Be;Qh=dt,jh=xt,tu=Dt,eu=Nt}function iu(_,b,P,N,W,Z,at){ls=An._x=An._y=!1,el(_,b,P,N,W,Z,at,!1,!0);let{left:dt,top:xt,width:Dt,height:Nt}=Be,Ut=Dt>0||Nt>0,jt=Qh!=dt||jh!=xt||tu!=Dt||eu!=Nt;if(Ut&&jt&&La(Be),An.setScale&&Ut&&jt){let Se=dt,_e=Dt,ue=xt,$t=Nt;if(D.ori==1&&(Se=xt,_e=Nt,ue=dt,$t=Dt),vn&&cs(E,Ci(Se,E),Ci(Se+_e,E)),xn)for(let Vt in y){let ze=y[Vt];Vt!=E&&ze.from==null&&ze.min!=Ne&&cs(Vt,Ci(ue+$t,Vt),Ci(ue,Vt))}il()}else ot.lock&&(ot._lock=!ot._lock,Ls(b,!0,_!=null));_!=null&&(cn(Jl,Qc),$r(Jl,i,Oe,Ge,O,Rt,null))}function vm(_,b,P,N,W,Z,at){if(ot._lock)return;Yt(_);let dt=ls;if(ls){let xt=!0,Dt=!0,Nt=10,Ut,jt;D.ori==0?(Ut=vn,jt=xn):(Ut=xn,jt=vn),Ut&&jt&&(xt=Oe<=Nt||Oe>=O-Nt,Dt=Ge<=Nt||Ge>=Rt-Nt),Ut&&xt&&(Oe=Oe<tr?0:O),jt&&Dt&&(Ge=Ge<er?0:Rt),Ls(null,!0,!0),ls=!1}Oe=-10,Ge=-10,nt.fill(null),Ls(null,!0,!0),dt&&(ls=dt)}function su(_,b,P,N,W,Z,at){ot._lock||(Yt(_),Gr(),il(),_!=null&&$r(Bd,i,Oe,Ge,O,Rt,null))}function ru(){A.forEach(Sb),F(i.width,i.height,!0)}Vs(Io,wr,ru);const sr={};sr.mousedown=nu,sr.mousemove=Jh,sr.mouseup=iu,sr.dblclick=su,sr.setSeries=(_,b,P,N)=>{let W=rn.match[2];P=W(i,b,P),P!=-1&&Ri(P,N,!0,!1)},pt&&(ge(Ud,v,nu),ge(Zl,v,Jh),ge(Fd,v,_=>{Yt(_),Xr(!1)}),ge(Od,v,vm),ge(Bd,v,su),ah.add(i),i.syncRect=Xr);const Da=i.hooks=n.hooks||{};function Sn(_,b,P){In?Te.push([_,b,P]):_ in Da&&Da[_].forEach(N=>{N.call(null,i,b,P)})}(n.plugins||[]).forEach(_=>{for(let b in _.hooks)Da[b]=(Da[b]||[]).concat(_.hooks[b])});const au=(_,b,P)=>P,rn=on({key:null,setSeries:!1,filters:{pub:Kd,sub:Kd},scales:[E,x[1]?x[1].scale:null],match:[Zd,Zd,au],values:[null,null]},ot.sync);rn.match.length==2&&rn.match.push(au),ot.sync=rn;const ou=rn.key,sl=Zp(ou);function $r(_,b,P,N,W,Z,at){rn.filters.pub(_,b,P,N,W,Z,at)&&sl.pub(_,b,P,N,W,Z,at)}sl.sub(i);function xm(_,b,P,N,W,Z,at){rn.filters.sub(_,b,P,N,W,Z,at)&&sr[_](null,b,P,N,W,Z,at)}i.pub=xm;function Sm(){sl.unsub(i),ah.delete(i),_n.clear(),eh(Io,wr,ru),l.remove(),Tt?.remove(),Sn("destroy")}i.destroy=Sm;function rl(){Sn("init",n,t),Hr(t||n.data,!1),G[E]?Jo(E,G[E]):Gr(),it=Be.show&&(Be.width>0||Be.height>0),tt=ft=!0,F(n.width,n.height)}return x.forEach(qs),A.forEach(Gi),e?e instanceof HTMLElement?(e.appendChild(l),rl()):e(i,rl):rl(),i}Dn.assign=on;Dn.fmtNum=Ih;Dn.rangeNum=Uo;Dn.rangeLog=Vo;Dn.rangeAsinh=Dh;Dn.orient=Ys;Dn.pxRatio=Me;Dn.join=uE;Dn.fmtDate=Fh,Dn.tzDate=yE;Dn.sync=Zp;{Dn.addGap=sb,Dn.clipGaps=$o;let n=Dn.paths={points:nm};n.linear=sm,n.stepped=ob,n.bars=lb,n.spline=hb}class lm{shown=new Map;observer;constructor(){this.observer=typeof IntersectionObserver>"u"?null:new IntersectionObserver(t=>{for(const e of t)this.shown.set(e.target,e.isIntersecting)})}watch(t){this.shown.set(t,!0),this.observer?.observe(t)}visible(t){return this.shown.get(t)??!0}}const xf=[{title:"ΔE = E − E₀",key:"dE",unit:"J",color:"#ffb347"},{title:"ΔJ₃ = J₃ − J₃(0)",key:"dJ3",unit:"kg m²/s",color:"#7dff8a"},{title:"z(t)",key:"z",unit:"m",color:"#59c3ff",events:!0},{title:"tension T(t)",key:"tension",unit:"N",color:"#ff5d73",events:!0}];function Mb(n){if(n===0)return"0";const t=Math.abs(n);return t>=.001&&t<1e4?String(+n.toPrecision(4)):n.toExponential(1)}class yb{constructor(t,e=()=>{}){this.container=t;let i=0;const s={drawClear:[()=>{i=performance.now()}],draw:[()=>e(performance.now()-i)]};for(const r of xf){const a=document.createElement("div");a.className="plot",t.appendChild(a),this.els.push(a),this.visibility.watch(a),this.shown.push({h:null,n:-1,t:NaN,ev:null});const o={title:`${r.title} [${r.unit}]`,width:this.width(),height:150,scales:{x:{time:!1}},legend:{show:!1},hooks:r.events?{...s,draw:[...s.draw??[],c=>this.markEvents(c)]}:s,cursor:{show:!0,drag:{x:!1,y:!1}},series:[{label:"t [s]"},{label:r.title,stroke:r.color,width:1.5}],axes:[{stroke:"#aab",grid:{stroke:"#2a2f3a"},ticks:{stroke:"#2a2f3a"}},{stroke:"#aab",size:64,grid:{stroke:"#2a2f3a"},ticks:{stroke:"#2a2f3a"},values:(c,l)=>l.map(Mb)}]};this.charts.push(new Dn(o,[[],[]],a))}new ResizeObserver(()=>this.resize()).observe(t)}container;charts=[];els=[];visibility=new lm;shown=[];events=[];width(){return Math.max(200,this.container.clientWidth-8)}resize(){for(const t of this.charts)t.setSize({width:this.width(),height:150})}markEvents(t){const[e,i]=[t.scales.x?.min,t.scales.x?.max];if(e===void 0||i===void 0||e===null||i===null)return;const{ctx:s,bbox:r}=t;s.save(),s.lineWidth=1,s.strokeStyle="#e0e0e0";for(const a of this.events){if(a.t<e||a.t>i)continue;const o=Math.round(t.valToPos(a.t,"x",!0))+.5;s.setLineDash(a.kind==="slack"?[4,3]:[]),s.beginPath(),s.moveTo(o,r.top),s.lineTo(o,r.top+r.height),s.stroke()}s.restore()}update(t,e=[]){this.events=e;const i=t.t.length,s=t.t[i-1]??NaN;xf.forEach((r,a)=>{const o=this.charts[a],c=this.els[a],l=this.shown[a];o===void 0||c===void 0||l===void 0||!this.visibility.visible(c)||l.h===t&&l.n===i&&Object.is(l.t,s)&&l.ev===e||(Object.assign(l,{h:t,n:i,t:s,ev:e}),o.setData([t.t,t[r.key]]))})}}function nc(n,t=.1){let e=1/0,i=-1/0;for(const a of n)Number.isFinite(a)&&(a<e&&(e=a),a>i&&(i=a));if(e>i)return{lo:-1,hi:1};const s=i-e,r=s>0?t*s:Math.max(.5,Math.abs(e)*.1);return{lo:e-r,hi:i+r}}function Eb(n,t,e){const i=Math.max(t===null?0:t-n,.2*e);return{lo:n-.15*i,hi:n+2.2*i}}function po(n){if(n===0)return"0";const t=Math.abs(n);return t>=.01&&t<1e4?String(+n.toPrecision(3)):n.toExponential(1)}class ic{constructor(t,e,i,s,r=150){this.xLabel=i,this.yLabel=s,this.height=r;const a=document.createElement("div");a.className="plot curve";const o=document.createElement("div");o.className="curve-title",o.textContent=e,a.appendChild(o),this.canvas=document.createElement("canvas"),this.canvas.setAttribute("aria-label",e),a.appendChild(this.canvas),t.appendChild(a),this.ctx=this.canvas.getContext("2d")}xLabel;yLabel;height;canvas;ctx;draw(t,e,i,s,r={}){const a=this.ctx;if(a===null)return;const o=Math.min(window.devicePixelRatio||1,2),c=Math.max(100,t),l=this.height;this.canvas.width!==Math.round(c*o)&&(this.canvas.width=Math.round(c*o),this.canvas.height=Math.round(l*o),this.canvas.style.width=`${c}px`,this.canvas.style.height=`${l}px`),a.setTransform(o,0,0,o,0,0),a.clearRect(0,0,c,l);const h=56,d=l-20,u=6,m=c-8,v=f=>h+(f-i.lo)/(i.hi-i.lo)*(m-h),M=f=>d-(f-s.lo)/(s.hi-s.lo)*(d-u);a.strokeStyle="#2a2f3a",a.strokeRect(h,u,m-h,d-u),a.fillStyle="#aab",a.font="11px system-ui, sans-serif",a.fillText(po(s.hi),4,u+10),a.fillText(po(s.lo),4,d),a.fillText(this.yLabel,4,(u+d)/2),a.fillText(po(i.lo),h,l-4);const p=po(i.hi);a.fillText(p,m-a.measureText(p).width,l-4),a.fillText(this.xLabel,(h+m)/2-10,l-4),a.save(),a.beginPath(),a.rect(h,u,m-h,d-u),a.clip(),r.hLine!==void 0&&r.hLine!==null&&this.line(a,h,M(r.hLine),m,M(r.hLine),"#ffb347"),r.vLine!==void 0&&r.vLine!==null&&this.line(a,v(r.vLine),u,v(r.vLine),d,"#888");for(const f of e){a.strokeStyle=f.color,a.lineWidth=1.5,a.beginPath();let x=!1;for(let A=0;A<f.x.length;A++){const y=f.x[A],R=f.y[A];if(!Number.isFinite(y)||!Number.isFinite(R)){x=!1;continue}const E=Math.max(-1e4,Math.min(1e4,M(R)));x?a.lineTo(v(y),E):a.moveTo(v(y),E),x=!0}a.stroke()}r.dot&&(a.fillStyle="#ff8c42",a.beginPath(),a.arc(v(r.dot[0]),M(r.dot[1]),3.5,0,2*Math.PI),a.fill()),a.restore()}line(t,e,i,s,r,a){t.strokeStyle=a,t.lineWidth=1,t.setLineDash([4,3]),t.beginPath(),t.moveTo(e,i),t.lineTo(s,r),t.stroke(),t.setLineDash([])}}function bb(n){return Math.atan2(Math.hypot(n[0],n[1]),-n[2])}class wb{constructor(t){this.container=t,this.phase=new ic(t,"phase portrait (z, ż) [m, m/s]","z [m]","ż"),this.potential=new ic(t,"V_eff(θ) and the energy E [J]","θ [rad]","J"),this.em=new ic(t,"energy–momentum map (J₃ [kg m²/s], E [J])","J₃","E");for(const e of[this.phase,this.potential,this.em])this.visibility.watch(e.canvas);this.note=document.createElement("p"),this.note.className="note",this.note.dataset.note="portraits",t.appendChild(this.note)}container;phase;potential;em;note;visibility=new lm;setModel(t){const e=hh(t)??"";this.note.textContent!==e&&(this.note.textContent=e)}updateEM(t,e){if(!this.visibility.visible(this.em.canvas))return;const i=Math.max(200,this.container.clientWidth-8);if(t===null){this.em.draw(i,[],{lo:-1,hi:1},{lo:-1,hi:1});return}const s=t.top.energy,r=nc([...t.boundary.j3.filter((o,c)=>(t.boundary.energy[c]??1/0)<2.6*s),e?.j3??0],.05),a={lo:t.bottom.energy-.15*s,hi:Math.max(2.6*s,(e?.energy??0)+.2*s)};this.em.draw(i,[{x:t.boundary.j3,y:t.boundary.energy,color:"#c9a0ff"}],r,a,{vLine:0,hLine:t.top.energy,dot:e?[e.j3,e.energy]:null})}update(t,e,i,s,r,a){const o=Math.max(200,this.container.clientWidth-8);if(this.visibility.visible(this.phase.canvas)){const l=e?[e.x[2],e.v[2]]:null,h=nc(e?[...t.z,e.x[2]]:t.z),d=nc(e?[...t.zdot,e.v[2]]:t.zdot);this.phase.draw(o,[{x:t.z,y:t.zdot,color:"#59c3ff"}],h,d,{dot:l})}if(!this.visibility.visible(this.potential.canvas))return;if(i===null||i.theta.length===0){this.potential.draw(o,[],{lo:0,hi:Math.PI},{lo:-1,hi:1});return}const c=Eb(i.minimum.v_eff,e?.energy??null,s*Math.max(Math.abs(r),1)*a);this.potential.draw(o,[{x:i.theta,y:i.v_eff,color:"#7dff8a"}],{lo:0,hi:Math.PI},c,{hLine:e?.energy??null,vLine:e?bb(e.x):null})}}async function lh(n,t){const e=await fetch(n,t),i=await e.json();if(!e.ok){const s=i.detail;throw new Error(typeof s=="string"?s:`${n}: HTTP ${e.status}`)}return i}function mo(n,t){return lh(n,{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(t)})}const go=n=>n instanceof Error?n.message:String(n);class Tb{constructor(t,e,i){this.store=t,this.reduced=e,this.explain=i}store;reduced;explain;veff=null;em=null;veffKey="";veffAt=-1/0;veffJ3=null;emKey="";exactEpoch=-1;reducedEpoch=-1;onFrames(){const t=this.store.status,e=this.store.trajectory[0],i=this.store.latest();if(!(t===null||e===void 0||i===null)){if(this.exactEpoch!==t.epoch&&this.fetchExact(t,e),this.reducedEpoch!==t.epoch&&this.fetchReduced(t,e),!Pm(t.model)){[this.veff,this.em,this.veffKey,this.emKey]=[null,null,"",""];return}this.fetchEM(t,e),this.fetchPotential(t,i)}}fetchPotential(t,e){const i=t.params,s=`${t.epoch}:${i.length}:${i.mass}:${i.g}`,r=performance.now(),a=Math.abs(e.j3-(this.veffJ3??NaN))>.001*Math.max(Math.abs(e.j3),1e-9);s===this.veffKey&&!(a&&r-this.veffAt>1e3)||(s!==this.veffKey&&(this.veff=null),[this.veffKey,this.veffAt,this.veffJ3]=[s,r,e.j3],mo("api/effective_potential",{length:i.length,mass:i.mass,g:i.g,j3:e.j3}).then(o=>{this.veffKey===s&&(this.veff=o)},o=>this.explain(`V_eff: ${go(o)}`)))}fetchEM(t,e){const i=t.params,s=`${i.length}:${i.mass}:${i.g}`;s!==this.emKey&&(this.emKey=s,this.em=null,i.g!==0&&mo("api/em_map",{length:i.length,mass:i.mass,g:i.g,x:e.x,v:e.v}).then(r=>{this.emKey===s&&(this.em=r)},r=>this.explain(`energy–momentum map: ${go(r)}`)))}fetchReduced(t,e){if(this.reducedEpoch=t.epoch,t.model!=="ideal"){this.reduced.setNote(hh(t.model)??`the reduced view is the ideal pendulum's; this is the ${t.model} model`);return}this.reduced.setNote(null);const i=t.params;mo("api/reduced",{length:i.length,mass:i.mass,g:i.g,x:e.x,v:e.v}).then(s=>{this.store.status?.epoch===t.epoch&&this.reduced.set(s)},s=>this.reduced.setNote(`reduced view: ${go(s)}`))}fetchExact(t,e){if(this.exactEpoch=t.epoch,t.model!=="ideal")return;const i=t.params;mo("api/exact",{length:i.length,mass:i.mass,g:i.g,x:e.x,v:e.v}).then(s=>{this.store.status?.epoch===t.epoch&&this.store.setExact(s)},s=>{this.store.status?.epoch===t.epoch&&this.store.setExact(null,go(s))})}}function Ab(n,t){const e=t*t;return[n.x[2]/t,n.v[2]/t,(n.v[0]**2+n.v[1]**2+n.v[2]**2)/e]}function Rb(n){const t=Math.max(...n.surface.sigma2.map(Math.abs),1e-9),e=Math.max(...n.orbit.sigma3,n.point[2],1e-9);return{s2:t,s3top:1.6*e+1e-9}}class Vh{constructor(t,e){this.container=t;const i=document.createElement("div");i.className="curve-title",i.textContent="reduced view (σ₁, σ₂, σ₃): J₃ surface ∩ energy plane",t.appendChild(i),this.renderer=new _p({antialias:e.antialias,preserveDrawingBuffer:!0}),this.renderer.localClippingEnabled=!0,this.renderer.setPixelRatio(e.pixelRatio),this.renderer.domElement.className="reduced-canvas",t.appendChild(this.renderer.domElement),this.note=document.createElement("p"),this.note.className="note",t.appendChild(this.note),this.scene.background=new le(1448482),this.camera.up.set(0,0,1),this.camera.position.set(3.2,-3.6,2.2),this.controls=new xp(this.camera,this.renderer.domElement),this.point=new bn(new Gs(.05,16,12),new ys({color:16747586,depthTest:!1,transparent:!0})),this.point.renderOrder=3,this.point.visible=!1,this.scene.add(this.group,this.point,new rp(1.2)),this.resize(),new ResizeObserver(()=>this.resize()).observe(t),new IntersectionObserver(s=>{this.visible=s.some(r=>r.isIntersecting)}).observe(this.renderer.domElement),this.controls.addEventListener("change",()=>{this.dirty=!0})}container;renderer;camera=new Ln(35,1,.01,100);controls;scene=new Kf;group=new Mr;point;scales=null;note;visible=!1;lastDrawn=-1/0;dirty=!0;resize(){const t=Math.max(200,this.container.clientWidth-8),e=220;this.renderer.setSize(t,e,!1),this.renderer.domElement.style.width=`${t}px`,this.renderer.domElement.style.height=`${e}px`,this.camera.aspect=t/e,this.camera.updateProjectionMatrix()}setNote(t){this.note.textContent=t??"",t!==null&&this.set(null)}set(t){for(const E of[...this.group.children]){this.group.remove(E);const g=E;g.geometry?.dispose(),g.material?.dispose()}if(this.scales=t===null?null:Rb(t),this.dirty=!0,t===null||this.scales===null)return;const{s2:e,s3top:i}=this.scales,s=(E,g,T)=>new V(E,g/e,2*T/i-1),r=[new Si(new V(0,0,-1),1)],{sigma1:a,sigma2:o,sigma3:c}=t.surface,l=[];a.forEach((E,g)=>o.forEach((T,z)=>l.push(...s(E,T,c[g]?.[z]??NaN).toArray())));const h=[],d=o.length;for(let E=0;E+1<a.length;E++)for(let g=0;g+1<d;g++){const T=E*d+g;h.push(T,T+d,T+1,T+1,T+d,T+d+1)}const u=new ln;u.setAttribute("position",new We(l,3)),u.setIndex(h);const m={color:9417727,transparent:!0,opacity:.25,side:ci,clippingPlanes:r};this.group.add(new bn(u,new ys({...m,depthWrite:!1}))),this.group.add(new bn(u.clone(),new ys({...m,wireframe:!0,opacity:.25})));const{h:v,gamma:M}=t.plane,p=(E,g)=>s(E,g,2*(v-M*E)),f=new ln().setFromPoints([p(-1,-e),p(1,-e),p(1,e),p(-1,e)]);f.setIndex([0,1,2,0,2,3]);const x=new ys({color:16757575,transparent:!0,opacity:.22,side:ci,depthWrite:!1,clippingPlanes:[...r,new Si(new V(0,0,1),1)]});this.group.add(new bn(f,x));const A=t.orbit,y=new ln().setFromPoints(A.sigma1.map((E,g)=>s(E,A.sigma2[g]??NaN,A.sigma3[g]??NaN))),R=new Xs(y,new Ts({color:5882879,depthTest:!1,transparent:!0}));R.renderOrder=2,this.group.add(R),this.point.visible=!0}update(t,e){if(this.scales!==null&&t!==null){const[s,r,a]=Ab(t,e);this.point.position.set(s,r/this.scales.s2,2*a/this.scales.s3top-1)}this.point.visible=this.scales!==null&&t!==null;const i=performance.now();!this.visible||!this.dirty&&i-this.lastDrawn<Vh.MIN_INTERVAL||(this.lastDrawn=i,this.dirty=!1,this.controls.update(),this.renderer.render(this.scene,this.camera))}static MIN_INTERVAL=250}class Cb{constructor(t){this.intervalMs=t}intervalMs;last=-1/0;due(t){return t-this.last<this.intervalMs?!1:(this.last=t,!0)}reset(){this.last=-1/0}}class Pb{last=null;changed(t){const e=this.last;return e!==null&&e.length===t.length&&t.every((i,s)=>Object.is(i,e[s]))?!1:(this.last=[...t],!0)}}class Lb{sums=new Map;add(t,e){const i=this.sums.get(t);i===void 0?this.sums.set(t,{ms:e,count:1}):(i.ms+=e,i.count++)}take(){const t={};for(const[e,i]of this.sums)t[e]={ms:i.ms/i.count,count:i.count};return this.sums.clear(),t}}function Db(n){const t={model:n.model,length:n.params.length,mass:n.params.mass,g:n.params.g,params:{...n.model_params},x:n.start.x,v:n.start.v,method:n.method,dt:n.dt,t0:n.t0,t_end:Math.max(n.t0+100,Math.ceil(n.t))},e=n.title??n.scenario;return e&&(t.title=`${e} (from the lab)`),t}function _s(n){return Object.is(n,-0)?"-0":String(n)}function Nb(n){const t=new URLSearchParams;return n.scenario!==void 0&&t.set("s",n.scenario),n.model!==void 0&&t.set("model",n.model),n.modelParams!==void 0&&Object.keys(n.modelParams).length>0&&t.set("mp",Object.entries(n.modelParams).map(([e,i])=>`${e}:${_s(i)}`).join(",")),n.length!==void 0&&t.set("l",_s(n.length)),n.mass!==void 0&&t.set("m",_s(n.mass)),n.g!==void 0&&t.set("g",_s(n.g)),n.method!==void 0&&t.set("method",n.method),n.dt!==void 0&&t.set("dt",_s(n.dt)),n.timeScale!==void 0&&t.set("ts",_s(n.timeScale)),n.x!==void 0&&t.set("x",n.x.map(_s).join(",")),n.v!==void 0&&t.set("v",n.v.map(_s).join(",")),n.paused===!0&&t.set("paused","1"),t.toString()}const Ib=/^[A-Za-z0-9_.-]{1,100}$/;function sc(n){if(!/^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(n.trim()))return null;const t=Number(n);return Number.isFinite(t)?t:null}function Ub(n){const t=new URLSearchParams(n.startsWith("?")?n.slice(1):n),e={},i=[],s=new Set(["s","model","mp","l","m","g","method","dt","ts","x","v","paused"]);for(const y of t.keys())s.has(y)||i.push(`unknown URL key ${y}`);const r=y=>{const R=t.get(y);if(R!==null){if(!Ib.test(R)){i.push(`${y} = ${JSON.stringify(R)} is not a name`);return}return R}},a=y=>{const R=t.get(y);if(R===null)return;const E=sc(R);return E===null&&i.push(`${y} = ${JSON.stringify(R)} is not a finite number`),E??void 0},o=y=>{const R=t.get(y);if(R===null)return;const E=R.split(",").map(sc);if(E.length!==3||E.some(g=>g===null)){i.push(`${y} = ${JSON.stringify(R)} is not three finite numbers`);return}return E},c=r("s");c!==void 0&&(e.scenario=c);const l=r("model");l!==void 0&&(e.model=l);const h=t.get("mp");if(h!==null){const y={};for(const R of h.split(",")){const[E,g,...T]=R.split(":"),z=g===void 0?null:sc(g);if(E===void 0||!/^[A-Za-z_][A-Za-z0-9_]{0,40}$/.test(E)||z===null||T.length>0){i.push(`mp: ${JSON.stringify(R)} is not name:number`);continue}y[E]=z}Object.keys(y).length>0&&(e.modelParams=y)}const d=a("l");d!==void 0&&(e.length=d);const u=a("m");u!==void 0&&(e.mass=u);const m=a("g");m!==void 0&&(e.g=m);const v=r("method");v!==void 0&&(e.method=v);const M=a("dt");M!==void 0&&(e.dt=M);const p=a("ts");p!==void 0&&(e.timeScale=p);const f=o("x"),x=o("v");f===void 0!=(x===void 0)&&i.length===0?i.push("the start needs both x and v"):f!==void 0&&x!==void 0&&(e.x=f,e.v=x);const A=t.get("paused");return A!==null&&(e.paused=A==="1"||A==="true"),{value:e,problems:i}}function Sf(n){const t={model:n.model,length:n.params.length,mass:n.params.mass,g:n.params.g,method:n.method,dt:n.dt,timeScale:n.time_scale,x:n.start.x,v:n.start.v};return n.scenario!==null&&(t.scenario=n.scenario),Object.keys(n.model_params).length>0&&(t.modelParams={...n.model_params}),n.paused&&(t.paused=!0),t}function Mf(n){const t=[];n.scenario!==void 0&&t.push({type:"load_scenario",name:n.scenario}),n.model!==void 0&&t.push({type:"set_model",model:n.model,params:{...n.modelParams}});const e={type:"set_params"};n.length!==void 0&&(e.length=n.length),n.mass!==void 0&&(e.mass=n.mass),n.g!==void 0&&(e.g=n.g),Object.keys(e).length>1&&t.push(e);const i={type:"set_method"};return n.method!==void 0&&(i.method=n.method),n.dt!==void 0&&(i.dt=n.dt),Object.keys(i).length>1&&t.push(i),n.timeScale!==void 0&&t.push({type:"set_time_scale",time_scale:n.timeScale}),n.x!==void 0&&n.v!==void 0&&t.push({type:"set_state",x:n.x,v:n.v}),t.length>0&&t.push({type:"reset"}),n.paused===!0&&t.push({type:"pause"}),t}function _i(n){const t=document.getElementById(n);if(t===null)throw new Error(`#${n} missing from index.html`);return t}function rc(n,t){const e=document.createElement("a");e.href=t,e.download=n,document.body.appendChild(e),e.click(),e.remove()}async function Fb(){const n=new QM,t=_i("message");let e=null;const i=(I,B=!1)=>{t.textContent=I,t.classList.toggle("info",B),t.classList.add("shown"),e!==null&&clearTimeout(e),e=setTimeout(()=>t.classList.remove("shown"),6e3)},[s,r]=await Promise.all([lh("api/schema"),lh("api/scenarios")]);n.tickHz=s.tick_hz;const a=cy(hy(),window.devicePixelRatio);a.software&&(_i("render").textContent=" · software WebGL: no antialiasing",_i("render").title=`${a.renderer??""}: drawn without multisampling for the frame rate`);const o=new yy(_i("scene"),a),c={...dy},l=new Lb,h=new yb(_i("plots"),I=>l.add("plots drawn (uPlot)",I)),d=new wb(_i("portraits")),u=new Vh(_i("reduced"),a),m=new Bm(_i("data")),v=Ub(window.location.search);v.problems.length>0&&i(`link: ${v.problems.join("; ")}`);let M=Mf(v.value),p=null;const f=I=>{(p===null||!p.send(I))&&i("not connected to the server")},x=new wy(_i("gui"),s,r,c,{send:f,explain:i,downloadCSV:()=>{const I=new Blob([n.toCSV()],{type:"text/csv"}),B=URL.createObjectURL(I);rc(`pendulab-${n.status?.scenario??"lab"}.csv`,B),setTimeout(()=>URL.revokeObjectURL(B),1e4)},downloadTOML:()=>{const I=n.status;if(I===null)return i("not connected to the server");fetch("api/scenario.toml",{method:"POST",headers:{"content-type":"application/json"},body:JSON.stringify(Db(I))}).then(async B=>{if(!B.ok)throw new Error((await B.json()).detail??`HTTP ${B.status}`);const L=URL.createObjectURL(await B.blob());rc(`pendulab-${I.scenario??"lab"}.toml`,L),setTimeout(()=>URL.revokeObjectURL(L),1e4)}).catch(B=>i(`scenario download: ${B instanceof Error?B.message:String(B)}`))},screenshot:()=>rc(`pendulab-${n.status?.scenario??"lab"}.png`,o.screenshot()),copyLink:()=>{const I=window.location.href;navigator.clipboard?.writeText(I).then(()=>i("link copied: it reproduces this scenario",!0),()=>i(I))??i(I)},viewChanged:(I,B)=>{o.setTopView(B),o.setStereo(I.stereo)}}),A=new Tb(n,u,i),y=I=>{n.onStatus(I),x.sync(I),o.setLength(I.params.length),o.setModel(I.model),d.setModel(I.model),M.length===0&&window.history.replaceState(null,"",`?${Nb(Sf(I))}`)};p=new Rm(Am(window.location),{onOpen:()=>{n.setConnected(!0),_i("conn").textContent="connected"},onClose:()=>{n.setConnected(!1),_i("conn").textContent="disconnected: retrying…",n.status!==null&&(M=Mf(Sf(n.status)))},onFrames:I=>{const B=performance.now();n.onFrames(I),A.onFrames(),l.add("frames received",performance.now()-B)},onNotice:I=>{if(I.type==="error"){n.onError(I),i(I.command?`${I.command}: ${I.message}`:I.message);return}if(I.type==="event"){n.onEvent(I),i(Dm(I),!0);return}if(y(I),M.length>0){const B=M;M=[];for(const L of B)f(L)}},onProtocolError:I=>i(`protocol: ${I}`)});let R=0;const E=dh((I,B)=>{f({type:"set_state",x:I,v:B,project:!0})},50),g=()=>{n.status?.paused===!1&&f({type:"pause"})};o.enableDrag((I,B)=>{B==="start"&&g(),E(I,[0,0,0]),B==="end"&&i("start set by dragging (at rest there): press start to release it",!0)},(I,B,L)=>{if(L==="start"){g(),i("pull the arrow to set the start velocity",!0);return}if(B===null)return;E(I,B.v);const G=B.capped?" (capped: the most the arrow sets, 4√(g l))":"";i(L==="end"?`start velocity set: |v| = ${B.speed.toFixed(2)} m/s${G}; press start to run from it`:`start velocity |v| = ${B.speed.toFixed(2)} m/s${G}`,!0)}),window.pendulab={store:n,drawn:()=>R,send:f,screenshot:()=>o.screenshot(),bobOnScreen:()=>o.bobOnScreen(),handleOnScreen:()=>o.handleOnScreen(),quality:()=>a,frameCosts:()=>l.take()};let T=performance.now();const z=new Cb(100),U=new Pb,D=I=>{const B=(I-T)/1e3;T=I;let L=performance.now();n.advancePlayhead(B);const G=n.displayed(),Y=n.status?.params,k=ty(n.status?.model_params),{start:lt,end:K}=n.trailRange(c.trailSeconds),Q=Y?.mass??1,nt=Y?.g??9.81,ut=U.changed([G,n.trail,lt,K,Q,nt,...k,...Object.values(c)]);ut&&o.update(G,{frames:n.trail,start:lt,end:K},c,Q,nt,k);let ot=performance.now();l.add("scene update",ot-L),o.draw(ut)?(R++,L=performance.now(),l.add("scene render (submit)",L-ot)):L=ot,z.due(I)&&(h.update(n.history,n.events),ot=performance.now(),l.add("plots setData",ot-L),d.update(n.history,G,A.veff,Y?.mass??1,Y?.g??9.81,Y?.length??1),d.updateEM(A.em,G),L=performance.now(),l.add("portraits",L-ot),u.update(G,Y?.length??1),ot=performance.now(),l.add("reduced view",ot-L),m.update(G,n),l.add("data panel",performance.now()-ot)),requestAnimationFrame(D)};requestAnimationFrame(D)}Fb().catch(n=>{const t=document.getElementById("message");t&&(t.textContent=`the lab could not start: ${n instanceof Error?n.message:String(n)}`,t.classList.add("shown")),console.error(n)});
